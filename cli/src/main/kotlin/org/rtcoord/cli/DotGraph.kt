package org.rtcoord.cli

import org.rtcoord.LifeCycle

/**
 * A component network as Graphviz DOT: one box per component, coloured by state, one edge per connection from out-port
 * to in-port (service connections without direction). Ports the network reaches outside itself are dashed boxes. Output
 * is sorted, so the same system prints the same text.
 */
internal class DotGraph(val vertices: List<Vertex>, val edges: List<Edge>) {
    /** A component ([state] known) or a port outside the network ([state] null). */
    data class Vertex(val id: String, val label: String, val state: LifeCycle?)

    /** A connection from port [tail] of [from] to port [head] of [to], labelled with what it carries. */
    data class Edge(
        val from: String,
        val to: String,
        val tail: String,
        val head: String,
        val label: String?,
        val directed: Boolean,
    )

    /** The DOT text. */
    fun render(): String = buildString {
        appendLine("digraph rtsystem {")
        appendLine("  rankdir=LR;")
        appendLine("  node [shape=box, style=\"rounded,filled\", fontname=\"Helvetica\"];")
        appendLine("  edge [fontname=\"Helvetica\", fontsize=10];")
        vertices
            .sortedBy { it.id }
            .forEach { vertex ->
                val style = if (vertex.state == null) "style=dashed, " else ""
                // Escaped apart and joined by DOT's own line break, which must not be escaped again.
                val label =
                    listOfNotNull(vertex.label, vertex.state?.let(::stateLabel))
                        .joinToString("\\n", transform = ::escape)
                appendLine("  ${quote(vertex.id)} [${style}label=\"$label\", fillcolor=\"${fill(vertex.state)}\"];")
            }
        edges.sortedWith(compareBy({ it.from }, { it.to }, { it.tail }, { it.head })).forEach { edge ->
            val attributes =
                listOfNotNull(
                    "taillabel=${quote(edge.tail)}",
                    "headlabel=${quote(edge.head)}",
                    edge.label?.let { "label=${quote(it)}" },
                    "dir=none".takeUnless { edge.directed },
                )
            appendLine("  ${quote(edge.from)} -> ${quote(edge.to)} [${attributes.joinToString(", ")}];")
        }
        appendLine("}")
    }

    private fun quote(text: String) = "\"" + escape(text) + "\""

    private fun escape(text: String) = text.replace("\\", "\\\\").replace("\"", "\\\"")

    private fun fill(state: LifeCycle?): String =
        when (state) {
            LifeCycle.ACTIVE -> "#c8e6c9"
            LifeCycle.INACTIVE -> "#bbdefb"
            LifeCycle.ERROR -> "#ffcdd2"
            null -> "#ffffff"
            else -> "#eeeeee"
        }
}
