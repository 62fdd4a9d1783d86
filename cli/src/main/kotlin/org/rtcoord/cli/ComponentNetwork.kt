@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.cli

import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.ComponentNode
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.Node
import org.rtcoord.PortKind
import org.rtcoord.PortSnapshot
import org.rtcoord.RtcPath
import org.rtcoord.internal.componentsListed

/**
 * The components below [top] and the connections of their ports, as a [DotGraph]. Works from what discovery read; only
 * connections leading outside the network cost a call, to name their far end.
 */
internal class ComponentNetwork(private val top: Node) {
    /** Every component below [top] once: under its naming context rather than under its manager. */
    val components: List<ComponentNode> =
        componentsListed(listOf(top)) { it.snapshots.value != null }
            .sortedBy { component -> component.path.names.count { it.endsWith(".mgr") } }

    /** The graph. */
    suspend fun graph(): DotGraph = coroutineScope {
        // Both ports of a connection list the same connector id: grouping by it pairs the ends inside the network.
        val inside =
            components
                .flatMap { component ->
                    snapshot(component).ports.flatMap { port ->
                        port.connectors.map { it.id to endOf(component, port) }
                    }
                }
                .groupBy({ it.first }, { it.second })
        val outside =
            inside
                .filterValues { it.size == 1 }
                .map { (id, ends) -> async { id to farEnds(ends.single(), id) } }
                .awaitAll()
                .toMap()
        val edges = inside.flatMap { (id, ends) -> edges(ends + outside[id].orEmpty()) }
        val vertices =
            components.map { DotGraph.Vertex(idOf(it.path), snapshot(it).instanceName, snapshot(it).overallState) } +
                outside.values.flatten().map { DotGraph.Vertex(it.vertex, it.vertex, null) }.distinct()
        DotGraph(vertices, edges)
    }

    /** A vertex id: the path below [top] when there is one, else the whole path. */
    private fun idOf(path: RtcPath): String {
        val below = path.names.drop(top.path.names.size).joinToString("/")
        return if (!top.path.isRoot && path.startsWith(top.path) && below.isNotEmpty()) below else path.toString()
    }

    /**
     * The ports outside the network at the far end of connector [id] of [near]. They are taken to flow the other way
     * from [near], which is all a port outside the tree tells.
     */
    private suspend fun farEnds(near: End, id: String): List<End> {
        val component = components.first { idOf(it.path) == near.vertex }
        val kind =
            when (near.kind) {
                PortKind.DATA_OUT -> PortKind.DATA_IN
                PortKind.DATA_IN -> PortKind.DATA_OUT
                else -> near.kind
            }
        val own = snapshot(component).port(near.port)?.fullName
        return component
            .port(near.port)
            .connections()
            .filter { it.id == id }
            .flatMap { connection ->
                connection.ports
                    .filter { it.fullName != own }
                    .map { far ->
                        End(
                            far.path?.withPort(null)?.toString() ?: far.fullName.substringBefore('.'),
                            far.fullName.substringAfter('.'),
                            kind,
                            null,
                        )
                    }
            }
    }

    /**
     * Edges from each out-port end to each in-port end; without such a pair, one undirected edge between the first two.
     */
    private fun edges(ends: List<End>): List<DotGraph.Edge> {
        val label = ends.firstNotNullOfOrNull { it.dataType }?.substringAfterLast('/')?.substringBefore(':')
        val outs = ends.filter { it.kind == PortKind.DATA_OUT }
        val ins = ends.filter { it.kind == PortKind.DATA_IN }
        if (outs.isNotEmpty() && ins.isNotEmpty()) {
            return outs.flatMap { out ->
                ins.map { DotGraph.Edge(out.vertex, it.vertex, out.port, it.port, label, directed = true) }
            }
        }
        val (a, b) = ends.takeIf { it.size >= 2 } ?: return emptyList()
        return listOf(DotGraph.Edge(a.vertex, b.vertex, a.port, b.port, label, directed = false))
    }

    private fun snapshot(component: ComponentNode) = component.snapshots.value!!

    /** One port of a connection: the vertex it belongs to, its name, kind and data type. */
    private data class End(val vertex: String, val port: String, val kind: PortKind, val dataType: String?)

    private fun endOf(component: ComponentNode, port: PortSnapshot) =
        End(idOf(component.path), port.name, port.kind, port.dataType)
}
