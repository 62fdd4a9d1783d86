package org.rtcoord.dsl

import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.CountDownLatch
import java.util.concurrent.Executors
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.asCoroutineDispatcher
import kotlinx.coroutines.cancel
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.Overlap
import org.rtcoord.dsl.internal.HandlerQueue
import org.rtcoord.fixtures.await

/** A listener's queue hands over the event that finds its handler idle, whatever comes before the handler runs. */
class HandlerQueueTest {
    /**
     * The events a queue of [overlap] hands to its handler when 0..5 are offered at once, right after it was made,
     * while the one thread of its scope is held.
     */
    private fun handledFromIdle(overlap: Overlap): List<Int> {
        val thread = Executors.newSingleThreadExecutor()
        val scope = CoroutineScope(SupervisorJob() + thread.asCoroutineDispatcher())
        try {
            val held = CountDownLatch(1)
            thread.execute { held.await() }
            val handled = CopyOnWriteArrayList<Int>()
            val queue = HandlerQueue(scope, overlap) { event: Int -> handled += event }
            (0..5).forEach(queue::offer)
            held.countDown()
            val last = if (overlap == Overlap.SKIP) 0 else 5
            await("the queue to hand over its last event") { last in handled }
            return handled.toList()
        } finally {
            scope.cancel()
            thread.shutdownNow()
        }
    }

    @Test
    fun `the event that finds the handler idle is handled, and the overlap shapes the rest`() {
        assertEquals(listOf(0, 1, 2, 3, 4, 5), handledFromIdle(Overlap.QUEUE))
        assertEquals(listOf(0, 5), handledFromIdle(Overlap.LATEST))
        assertEquals(listOf(0), handledFromIdle(Overlap.SKIP))
    }
}
