package org.rtcoord.bench

import java.io.PrintStream

/**
 * The one table a run prints: sections (one per benchmark and size), each with rows of measurements (count, min,
 * median, max, unit) or single values, and a comparison or note per row; notes that apply to the whole run follow the
 * table. Benchmarks add to it as they finish.
 */
internal class Report {
    private sealed interface Line

    private class Section(val title: String) : Line

    private class Row(val measure: String, val cells: List<String>, val notes: String) : Line

    private val lines = mutableListOf<Line>()
    private val footnotes = mutableListOf<String>()
    private val started = System.nanoTime()

    fun section(title: String) {
        lines += Section(title)
        progress(title)
    }

    /** A measured row: [samples]' count, min, median and max. */
    fun row(measure: String, samples: Samples, notes: String = "") {
        lines +=
            Row(
                measure,
                listOf(
                    samples.count.toString(),
                    figure(samples.min),
                    figure(samples.median),
                    figure(samples.max),
                    samples.unit,
                ),
                notes,
            )
        progress("  $measure: median ${figure(samples.median)} ${samples.unit} $notes")
    }

    /** A row with one value, not a distribution. */
    fun value(measure: String, value: Double, unit: String, notes: String = "") {
        lines += Row(measure, listOf("1", "", figure(value), "", unit), notes)
        progress("  $measure: ${figure(value)} $unit $notes")
    }

    /** A row that could not be measured, and why. */
    fun skipped(measure: String, why: String) {
        lines += Row(measure, listOf("", "", "", "", ""), "skipped: $why")
        progress("  $measure: skipped: $why")
    }

    /** A note printed under the table. */
    fun note(text: String) {
        footnotes += text
    }

    fun print(out: PrintStream) {
        val header = listOf("n", "min", "median", "max", "unit")
        val rows = lines.filterIsInstance<Row>()
        val measureWidth = (rows.map { it.measure.length + 2 } + 24).max()
        val widths =
            header.indices.map { column -> (rows.map { it.cells[column].length } + header[column].length).max() }
        fun cells(values: List<String>) =
            values.mapIndexed { column, value -> value.padStart(widths[column]) }.joinToString("  ")
        out.println("${"benchmark".padEnd(measureWidth)}  ${cells(header)}  notes")
        for (line in lines) {
            when (line) {
                is Section -> out.println(line.title)
                is Row ->
                    out.println(
                        "${("  " + line.measure).padEnd(measureWidth)}  ${cells(line.cells)}  ${line.notes}".trimEnd()
                    )
            }
        }
        if (footnotes.isNotEmpty()) out.println()
        footnotes.forEach { out.println("* $it") }
    }

    /** A progress line on stderr, with the time since the run started. */
    private fun progress(text: String) {
        val seconds = (System.nanoTime() - started) / 1_000_000_000
        System.err.println("bench %d:%02d %s".format(seconds / 60, seconds % 60, text.trim()))
    }
}
