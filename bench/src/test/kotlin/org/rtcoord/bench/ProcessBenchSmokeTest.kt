package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Test

/**
 * The benchmarks that start processes (rtcoord's commands and rtshell's) run end to end on a tiny system, with the
 * library rows they compare the processes with.
 */
class ProcessBenchSmokeTest {
    @Test
    fun `the benchmarks of whole processes run on a tiny system and land in one table`(): Unit = runBlocking {
        smokeRun(
            listOf(
                Benchmark.DISCOVERY,
                Benchmark.ROUNDTRIP,
                Benchmark.STARTUP,
                Benchmark.PROFILE,
                Benchmark.TEST,
                Benchmark.EXPLORE,
            ),
            sections =
                listOf(
                    "discovery, whole process, N=10",
                    "discovery, library in a warm JVM, N=10",
                    "discovery floor",
                    "coordinator round trip:",
                    "start-up, whole processes",
                    "start-up breakdown",
                    "profile restore, N=10",
                ),
            rows =
                listOf(
                    // A measured row has a count and a median: the library discovery ran its two repetitions.
                    Regex("""rtcoord RtcTree\.create \+ refresh\s+2\s"""),
                    Regex("""rtcoord SystemProfiles\.restore in a warm JVM\s+1\s"""),
                ),
        )
    }
}
