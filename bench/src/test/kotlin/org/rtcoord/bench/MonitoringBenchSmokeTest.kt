package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Test

/**
 * The monitoring benchmarks run end to end on a tiny system. A class apart from [DataBenchSmokeTest] and the other
 * smoke classes, so that the build's test JVMs share them: the bench is the build's last module, and its longest class
 * is how long it takes.
 */
class MonitoringBenchSmokeTest {
    @Test
    fun `the monitoring benchmarks run on a tiny system and land in one table`(): Unit = runBlocking {
        smokeRun(
            listOf(Benchmark.MONITORING),
            sections = listOf("monitoring cost:", "monitoring cost at scale:"),
            rows = listOf(Regex("""push, 20 components: live heap per component\s+1\s""")),
        )
    }
}
