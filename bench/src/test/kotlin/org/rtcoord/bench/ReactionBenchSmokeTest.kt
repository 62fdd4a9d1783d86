package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Test

/** The reaction benchmark runs end to end on a tiny system: state change to callback, by push and by poll. */
class ReactionBenchSmokeTest {
    @Test
    fun `the reaction benchmark runs on a tiny system and lands in one table`(): Unit = runBlocking {
        smokeRun(
            listOf(Benchmark.REACTION),
            sections = listOf("reaction:"),
            rows = listOf(Regex("""push \(ComponentObserver\)\s+\d+\s""")),
        )
    }
}
