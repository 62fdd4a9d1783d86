package org.rtcoord.bench

import java.io.ByteArrayOutputStream
import java.io.PrintStream
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue

/**
 * Runs [benchmarks] on a tiny system and returns the table it prints, having checked that it has a section starting
 * with each of [sections], a measured row matching each of [rows] (a label, then its count of repetitions), and nothing
 * failed. The figures themselves are never asserted.
 */
internal suspend fun smokeRun(benchmarks: List<Benchmark>, sections: List<String>, rows: List<Regex>): String {
    val report = Bench(BenchOptions.smoke(benchmarks), Installation.find()).run()
    val printed = ByteArrayOutputStream().also { report.print(PrintStream(it, true)) }.toString()
    println(printed)
    assertEquals(
        emptyList<String>(),
        sections.filter { section -> printed.lines().none { it.startsWith(section) } },
        "missing sections",
    )
    assertEquals(emptyList<String>(), printed.lines().filter { "failed:" in it }, "failed benchmarks")
    for (row in rows) assertTrue(row.containsMatchIn(printed), "no row matching $row")
    return printed
}
