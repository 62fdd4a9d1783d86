package org.rtcoord.cli

/**
 * [rows] as aligned text, each line starting with [indent]: every column but the last padded to its widest cell plus
 * two spaces. Trailing spaces are dropped.
 */
internal fun aligned(rows: List<List<String>>, indent: String = ""): List<String> {
    val widths =
        rows.fold(emptyList<Int>()) { widths, row ->
            row.indices.map { maxOf(widths.getOrElse(it) { 0 }, row[it].length) }
        }
    return rows.map { row ->
        indent +
            row.mapIndexed { column, cell -> if (column == row.lastIndex) cell else cell.padEnd(widths[column] + 2) }
                .joinToString("")
                .trimEnd()
    }
}
