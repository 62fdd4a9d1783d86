package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Test

/**
 * The benchmarks measured in the bench's own JVM run end to end on a tiny system. A class apart from
 * [ProcessBenchSmokeTest], whose benchmarks start processes, so that the build's two test JVMs run them side by side.
 */
class LibraryBenchSmokeTest {
    @Test
    fun `the benchmarks in this JVM run on a tiny system and land in one table`(): Unit = runBlocking {
        smokeRun(
            listOf(
                Benchmark.MICRO,
                Benchmark.REACTION,
                Benchmark.MONITORING,
                Benchmark.MEMORY,
                Benchmark.DATA,
                Benchmark.SIMULATION,
            ),
            sections =
                listOf(
                    "one call and one notification",
                    "reaction:",
                    "monitoring cost:",
                    "memory:",
                    "data: tap of a TimedDoubleSeq(181)",
                    "simulation start, N=10",
                ),
            rows =
                listOf(
                    Regex("""silence noticed after 100 ms\s+1\s"""),
                    Regex("""rtcoord SimulatedSystem\.start in a warm JVM\s+1\s"""),
                ),
        )
    }
}
