package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Test

/**
 * The event path's costs run end to end on a tiny system: monitoring and data. Classes apart from
 * [ReactionBenchSmokeTest], [CostBenchSmokeTest] and [ProcessBenchSmokeTest], so that the build's test JVMs share them.
 */
class LibraryBenchSmokeTest {
    @Test
    fun `the monitoring and data benchmarks run on a tiny system and land in one table`(): Unit = runBlocking {
        smokeRun(
            listOf(Benchmark.MONITORING, Benchmark.DATA),
            sections = listOf("monitoring cost:", "monitoring cost at scale:", "data: tap of a TimedDoubleSeq(181)"),
            rows =
                listOf(
                    Regex("""silence noticed after 100 ms\s+1\s"""),
                    Regex("""push, 20 components: live heap per component\s+1\s"""),
                    Regex("""loopback floor: a sample's bytes at 100 Hz, no CORBA\s+2\s"""),
                ),
        )
    }
}
