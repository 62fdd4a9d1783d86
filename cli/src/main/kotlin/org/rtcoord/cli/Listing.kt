package org.rtcoord.cli

import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSummary
import org.rtcoord.DirectoryNode
import org.rtcoord.LifeCycle
import org.rtcoord.Node
import org.rtcoord.PortKind
import org.rtcoord.ZombieNode
import org.rtcoord.cli.json.EntryJson
import org.rtcoord.cli.json.PortCountJson
import org.rtcoord.cli.json.PortCountsJson

/**
 * One node as a listing shows it. [summary] is what was read of a component. Dead registrations (shown with `*`) are
 * the [ZombieNode]s of a directory, and a component [foundDead] when read on its own (see
 * [org.rtcoord.RtcException.meansDead]).
 */
internal class Entry(val node: Node, val summary: ComponentSummary?, foundDead: Boolean = false) {
    val dead: Boolean = foundDead || node is ZombieNode

    /** The short form: directories end in `/`, dead registrations start with `*`, as in rtls. */
    val shortName: String
        get() =
            when {
                dead -> "*${node.name}"
                node is DirectoryNode -> "${node.name}/"
                else -> node.name
            }

    /** The columns before the name in the long form: state and four port counts, or `-` where they mean nothing. */
    val columns: List<String>
        get() {
            val summary = summary?.takeUnless { dead } ?: return List(5) { "-" }
            val ports = summary.ports
            fun count(kind: PortKind?) =
                ports
                    .filter { kind == null || it.kind == kind }
                    .let { "${it.size}/${it.count { port -> port.connectors.isNotEmpty() }}" }
            return listOf(
                stateLabel(summary.overallState),
                count(null),
                count(PortKind.DATA_IN),
                count(PortKind.DATA_OUT),
                count(PortKind.SERVICE),
            )
        }

    /** The entry for `--json`. */
    fun toJson(): EntryJson {
        val read = summary?.takeUnless { dead }
        return EntryJson(
            node.path.toString(),
            node.name,
            if (dead) "zombie" else node.kind.name.lowercase(),
            (node as? ZombieNode)?.cause?.message,
            read?.overallState?.name,
            read?.let(::portCounts),
        )
    }

    private fun portCounts(summary: ComponentSummary): PortCountsJson {
        fun count(kind: PortKind?): PortCountJson {
            val ports = summary.ports.filter { kind == null || it.kind == kind }
            return PortCountJson(ports.size, ports.count { it.connectors.isNotEmpty() })
        }
        return PortCountsJson(count(null), count(PortKind.DATA_IN), count(PortKind.DATA_OUT), count(PortKind.SERVICE))
    }
}

/** The entry for [node] as its last reading left it. */
internal fun entryOf(node: Node): Entry = Entry(node, (node as? ComponentNode)?.summaries?.value)

/**
 * Lines in rtls's long format: each column as wide as its widest cell plus two spaces, then the name (dead ones with
 * `*`).
 */
internal fun longLines(entries: List<Entry>): List<String> {
    if (entries.isEmpty()) return emptyList()
    val cells = entries.map { it.columns }
    val widths = (0 until 5).map { column -> cells.maxOf { it[column].length } + 2 }
    return entries.zip(cells).map { (entry, row) ->
        row.zip(widths).joinToString("") { (cell, width) -> cell.padEnd(width) } +
            if (entry.dead) "*${entry.node.name}" else entry.node.name
    }
}

/**
 * Names side by side in columns that fit [width], filled row by row as rtls does on a terminal; one per line when the
 * output is not a terminal ([width] null), for scripts.
 */
internal fun shortLines(entries: List<Entry>, width: Int?): List<String> {
    val names = entries.map { it.shortName }
    if (width == null || names.isEmpty()) return names
    val gap = 2
    val columns =
        (names.size downTo 1).first { count ->
            names.chunked(count).let { rows ->
                (0 until count).sumOf { c -> rows.maxOf { it.getOrNull(c)?.length ?: 0 } + gap } - gap <= width
            }
        }
    val rows = names.chunked(columns)
    val widths = (0 until columns).map { c -> rows.maxOf { it.getOrNull(c)?.length ?: 0 } }
    return rows.map { row ->
        row.mapIndexed { c, name -> name.padEnd(widths[c]) }.joinToString(" ".repeat(gap)).trimEnd()
    }
}

/** A state as rtshell prints it: `Active`, `Inactive`, `Error`, `Created`, `Unknown`. */
internal fun stateLabel(state: LifeCycle): String = state.name.lowercase().replaceFirstChar { it.uppercase() }
