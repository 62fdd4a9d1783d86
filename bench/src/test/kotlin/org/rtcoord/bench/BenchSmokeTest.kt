package org.rtcoord.bench

import java.io.ByteArrayOutputStream
import java.io.PrintStream
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * The harness runs end to end on a tiny system and prints one table with a section per benchmark and nothing failed.
 * The figures themselves are printed, never asserted.
 */
class BenchSmokeTest {
    @Test
    fun `every benchmark runs on a tiny system and lands in one table`(): Unit = runBlocking {
        val report = Bench(BenchOptions.smoke(), Installation.find()).run()
        val printed = ByteArrayOutputStream().also { report.print(PrintStream(it, true)) }.toString()
        println(printed)

        val sections =
            listOf(
                "one call and one notification",
                "discovery, whole process, N=10",
                "discovery, library in a warm JVM, N=10",
                "discovery floor",
                "reaction:",
                "monitoring cost:",
                "coordinator round trip:",
                "memory:",
                "start-up, whole processes",
                "start-up breakdown",
                "profile restore, N=10",
                "data: tap of a TimedDoubleSeq(181)",
                "simulation start, N=10",
            )
        assertEquals(
            emptyList<String>(),
            sections.filter { section -> printed.lines().none { it.startsWith(section) } },
            "missing sections",
        )
        assertEquals(emptyList<String>(), printed.lines().filter { "failed:" in it }, "failed benchmarks")
        // A measured row has a count and a median: the library discovery ran its two repetitions.
        assertTrue(
            Regex("""rtcoord RtcTree\.create \+ refresh\s+2\s""").containsMatchIn(printed),
            "no library discovery row",
        )
        assertTrue(
            Regex("""rtcoord SystemProfiles\.restore in a warm JVM\s+1\s""").containsMatchIn(printed),
            "no library restore row",
        )
        assertTrue(Regex("""silence noticed after 100 ms\s+1\s""").containsMatchIn(printed), "no silence detection row")
        assertTrue(
            Regex("""rtcoord SimulatedSystem\.start in a warm JVM\s+1\s""").containsMatchIn(printed),
            "no simulation start row",
        )
    }
}
