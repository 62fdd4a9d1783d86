package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Test

/** The benchmarks of what one thing costs run end to end on a tiny system: a call, a component's heap, a simulation. */
class CostBenchSmokeTest {
    @Test
    fun `the benchmarks of one call, one component and one simulation run on a tiny system and land in one table`():
        Unit = runBlocking {
        smokeRun(
            listOf(Benchmark.MICRO, Benchmark.MEMORY, Benchmark.SIMULATION),
            sections = listOf("one call and one notification", "memory:", "simulation start, N=10"),
            rows = listOf(Regex("""rtcoord SimulatedSystem\.start in a warm JVM\s+1\s""")),
        )
    }
}
