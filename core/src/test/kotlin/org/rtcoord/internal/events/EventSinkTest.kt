package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.CountDownLatch
import java.util.concurrent.Executors
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.asCoroutineDispatcher
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.NodeVanished
import org.rtcoord.Overlap
import org.rtcoord.RtcEvent
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.fixtures.await

/**
 * A sink hands events to its handler in order, shaped by its [Overlap], from a coroutine that lives only while there
 * are events to hand over: ten thousand idle registrations hold no coroutine.
 */
class EventSinkTest {
    private fun RtcTree.event(index: Int): RtcEvent = NodeVanished(root, RtcPath("/localhost/e$index"))

    private val RtcEvent.index: Int
        get() = (this as NodeVanished).child.toString().substringAfterLast("/e").toInt()

    private fun RtcTree.coroutines(): Int = core.scope.coroutineContext[Job]!!.children.count()

    /**
     * The events a sink of [overlap] hands over when 1..5 are offered while its handler is still busy with event 0, in
     * the order it handled them.
     */
    private fun handledWhileBusy(overlap: Overlap, bound: Int? = null, dropped: () -> Unit = {}): List<Int> =
        RtcTree(TreeConfig()).use { tree ->
            runBlocking {
                val handled = CopyOnWriteArrayList<Int>()
                val busy = CompletableDeferred<Unit>()
                val release = CompletableDeferred<Unit>()
                val sink =
                    EventSink(
                        tree.core.scope,
                        { true },
                        overlap,
                        { event ->
                            if (event.index == 0) {
                                busy.complete(Unit)
                                release.await()
                            }
                            handled += event.index
                        },
                        bound,
                        dropped,
                    )
                sink.offer(tree.event(0))
                withTimeout(5.seconds) { busy.await() }
                (1..5).forEach { sink.offer(tree.event(it)) }
                release.complete(Unit)
                val last = if (overlap == Overlap.SKIP) 0 else 5
                await("the sink to hand over its last event") { last in handled }
                sink.close()
                handled.toList()
            }
        }

    @Test
    fun `events are handled in order, and an idle sink holds no coroutine`() =
        RtcTree(TreeConfig()).use { tree ->
            val before = tree.coroutines()
            val handled = CopyOnWriteArrayList<Int>()
            val failed = AtomicInteger()
            val sink =
                EventSink(
                    tree.core.scope,
                    { it.index != 3 },
                    Overlap.QUEUE,
                    { event ->
                        handled += event.index
                        if (event.index == 1) {
                            failed.incrementAndGet()
                            error("handler fails")
                        }
                    },
                )
            repeat(2) { round -> (0..5).forEach { sink.offer(tree.event(it + 10 * round)) } }
            await("every event accepted to be handled") { handled.size == 11 }
            assertEquals(listOf(0, 1, 2, 4, 5, 10, 11, 12, 13, 14, 15), handled.toList(), "in order, 3 not accepted")
            assertEquals(1, failed.get(), "a failing handler is called again for the next event")
            await("the sink's coroutine to end once idle") { tree.coroutines() <= before }
            sink.close()
            sink.offer(tree.event(6))
            assertTrue(tree.coroutines() <= before, "a closed sink starts nothing")
        }

    /**
     * The events a sink of [overlap] hands over when 0..5 are offered at once, before its coroutine gets a thread: the
     * one thread of its dispatcher is held until all six are in.
     */
    private fun handledFromIdle(overlap: Overlap): List<Int> =
        RtcTree(TreeConfig()).use { tree ->
            val thread = Executors.newSingleThreadExecutor()
            try {
                val held = CountDownLatch(1)
                thread.execute { held.await() }
                val handled = CopyOnWriteArrayList<Int>()
                val scope = CoroutineScope(tree.core.scope.coroutineContext + thread.asCoroutineDispatcher())
                val sink = EventSink(scope, { true }, overlap, { handled += it.index })
                (0..5).forEach { sink.offer(tree.event(it)) }
                held.countDown()
                val last = if (overlap == Overlap.SKIP) 0 else 5
                await("the sink to hand over its last event") { last in handled }
                sink.close()
                handled.toList()
            } finally {
                thread.shutdownNow()
            }
        }

    @Test
    fun `the event that finds a sink idle is handled, whatever comes before its coroutine runs`() {
        assertEquals(listOf(0, 1, 2, 3, 4, 5), handledFromIdle(Overlap.QUEUE))
        assertEquals(listOf(0, 5), handledFromIdle(Overlap.LATEST))
        assertEquals(listOf(0), handledFromIdle(Overlap.SKIP))
    }

    @Test
    fun `QUEUE keeps every event offered while the handler runs`() {
        assertEquals(listOf(0, 1, 2, 3, 4, 5), handledWhileBusy(Overlap.QUEUE))
    }

    @Test
    fun `a bounded QUEUE drops the oldest and says so`() {
        val dropped = AtomicInteger()
        assertEquals(listOf(0, 3, 4, 5), handledWhileBusy(Overlap.QUEUE, bound = 3) { dropped.incrementAndGet() })
        assertEquals(2, dropped.get())
    }

    @Test
    fun `LATEST keeps only the newest event offered while the handler runs`() {
        assertEquals(listOf(0, 5), handledWhileBusy(Overlap.LATEST))
    }

    @Test
    fun `SKIP drops what is offered while the handler runs`() {
        assertEquals(listOf(0), handledWhileBusy(Overlap.SKIP))
    }
}
