package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/** The log records' benchmark runs end to end on a few senders: records sent, received and heard by the rules. */
class LogsBenchSmokeTest {
    @Test
    fun `the log records benchmark sends records that reach the rules, and lands in one table`(): Unit = runBlocking {
        val printed =
            smokeRun(
                listOf(Benchmark.LOGS),
                sections = listOf("logs: 1000 records/s", "logs: memory"),
                rows = listOf(Regex("""receiving CPU\s+1\s"""), Regex("""live heap after GC, view held\s+1\s""")),
            )
        // Delivered, not how fast: some record reached the rule on every record, and the rules on their components.
        val delivered = Regex("""records delivered to on\(logs\(\)\)\s+1\s+(\d+)""").find(printed)
        assertTrue((delivered?.groupValues?.get(1)?.toLong() ?: 0) > 0, "no record delivered")
        val attributed = Regex("""records attributed to components\s+1\s+(\d+)""").findAll(printed).toList()
        assertTrue(attributed.size == 2 && attributed.all { it.groupValues[1].toLong() > 0 }, "no record attributed")
    }
}
