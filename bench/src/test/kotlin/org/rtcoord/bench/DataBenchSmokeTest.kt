package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Test

/**
 * The data benchmarks run end to end on a tiny system: a tapped out-port and its silence noticed, a simulated out-port,
 * and the loopback floor.
 */
class DataBenchSmokeTest {
    @Test
    fun `the data benchmarks run on a tiny system and land in one table`(): Unit = runBlocking {
        smokeRun(
            listOf(Benchmark.DATA),
            sections = listOf("data: tap of a TimedDoubleSeq(181)"),
            rows =
                listOf(
                    Regex("""silence noticed after 100 ms\s+1\s"""),
                    Regex("""loopback floor: a sample's bytes at 100 Hz, no CORBA\s+1\s"""),
                ),
        )
    }
}
