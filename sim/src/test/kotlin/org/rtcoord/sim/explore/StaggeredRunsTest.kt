package org.rtcoord.sim.explore

import java.util.concurrent.atomic.AtomicInteger
import kotlin.coroutines.EmptyCoroutineContext
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.delay
import kotlinx.coroutines.test.currentTime
import kotlinx.coroutines.test.runTest
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test

/** How an exploration's runs share the machine, on virtual time: each once, so many at once, their starts apart. */
class StaggeredRunsTest {
    @Test
    fun `every run is made once, no more at once than asked, the workers starting a stagger apart`() = runTest {
        val started = mutableListOf<Pair<Long, Long>>()
        val running = AtomicInteger()
        var most = 0
        staggeredRuns(3, 10, dispatcher = EmptyCoroutineContext) { index ->
            started += index to currentTime
            most = maxOf(most, running.incrementAndGet())
            delay(1.seconds)
            running.decrementAndGet()
        }
        assertEquals((0L until 10).toList(), started.map { it.first }.sorted())
        assertEquals(3, most)
        // Runs of one length that started a stagger apart stay apart.
        val stagger = STAGGER.inWholeMilliseconds
        assertEquals(listOf(0L, stagger, 2 * stagger, 1000L, 1000 + stagger), started.take(5).map { it.second })
    }

    @Test
    fun `no run starts once told to stop, and those under way finish`() = runTest {
        val finished = mutableListOf<Long>()
        staggeredRuns(2, Long.MAX_VALUE, { currentTime < 2500 }, EmptyCoroutineContext) { index ->
            delay(1.seconds)
            finished += index
        }
        // Worker 0 starts runs at 0, 1000 and 2000 ms; worker 1 at 100, 1100 and 2100 ms.
        assertEquals(listOf(0L, 1, 2, 3, 4, 5), finished.sorted())
    }
}
