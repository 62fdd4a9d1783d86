package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.runTest
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * The tree's poll schedule on virtual time: reads spread over the period, and even degradation when they cannot keep
 * up.
 */
@OptIn(ExperimentalCoroutinesApi::class)
class PollScheduleTest {
    /** A component whose every read takes [readTime]; it records when each read started. */
    private class Component(
        private val scope: CoroutineScope,
        private val readTime: Duration,
        private val clock: () -> Long,
    ) : PollSchedule.Member {
        val reads = mutableListOf<Long>()

        override fun tick(done: () -> Unit) {
            reads += clock()
            scope.launch {
                delay(readTime)
                done()
            }
        }
    }

    private class Run(val components: List<Component>, val missed: Long, val warnings: List<Pair<Int, Duration>>)

    private fun TestScope.poll(count: Int, period: Duration, inFlight: Int, readTime: Duration, window: Duration): Run {
        var missed = 0L
        val warnings = mutableListOf<Pair<Int, Duration>>()
        val reads = CoroutineScope(coroutineContext + Job())
        val schedule =
            PollSchedule(
                backgroundScope,
                period,
                inFlight,
                { missed += it },
                { members, achieved -> warnings += members to achieved },
                testScheduler.timeSource,
            )
        val components = List(count) { Component(reads, readTime) { testScheduler.currentTime } }
        components.forEach(schedule::add)
        testScheduler.advanceTimeBy(window)
        schedule.stop()
        reads.coroutineContext[Job]!!.cancel()
        return Run(components, missed, warnings)
    }

    @Test
    fun `reads are spread over the period, each component once per tick, and none is missed`() = runTest {
        val run =
            poll(count = 100, period = 100.milliseconds, inFlight = 8, readTime = 2.milliseconds, window = 10.seconds)

        // 100 ticks of each in 10 s, give or take the one under way at the end.
        run.components.forEach { assertTrue(it.reads.size in 99..100, "reads: ${it.reads.size}") }
        // Component i is read at i ms of every period, or up to a slice (5 ms, a twentieth) earlier with
        // those due within it: spread, never a burst of 100 at once.
        run.components.forEachIndexed { index, component ->
            component.reads.forEach { start ->
                assertTrue((index - start % 100) in 0..5, "component $index read at $start")
            }
        }
        val perMillisecond = run.components.flatMap { it.reads }.groupingBy { it }.eachCount().values.max()
        assertEquals(6, perMillisecond, "reads starting in the same millisecond")
        assertEquals(0, run.missed)
        assertEquals(emptyList<Pair<Int, Duration>>(), run.warnings)
    }

    @Test
    fun `a round held up once catches up and misses no tick`() = runTest {
        var missed = 0L
        val reads = CoroutineScope(coroutineContext + Job())
        // One read at a time; the first read of the ninth component (due at 80 ms) takes 40 ms, holding the
        // tenth (due at 90 ms) until 120 ms, past the end of the round.
        val schedule =
            PollSchedule(backgroundScope, 100.milliseconds, 1, { missed += it }, { _, _ -> }, testScheduler.timeSource)
        var first = true
        val slow = PollSchedule.Member { done ->
            val readTime = if (first) 40.milliseconds else 1.milliseconds
            first = false
            reads.launch {
                delay(readTime)
                done()
            }
        }
        val others = List(9) { Component(reads, 1.milliseconds) { testScheduler.currentTime } }
        others.take(8).forEach(schedule::add)
        schedule.add(slow)
        schedule.add(others.last())
        testScheduler.advanceTimeBy(2.seconds)
        schedule.stop()
        reads.coroutineContext[Job]!!.cancel()

        others.forEach { assertTrue(it.reads.size in 19..20, "reads: ${it.reads.size}") }
        assertEquals(0, missed)
    }

    @Test
    fun `when reads cannot keep up every component is read at the same lower rate and it is said once`() = runTest {
        // 1000 components at 10 Hz want 10,000 reads a second; 8 reads of 4 ms at once sustain 2000.
        val run =
            poll(count = 1000, period = 100.milliseconds, inFlight = 8, readTime = 4.milliseconds, window = 20.seconds)

        val counts = run.components.map { it.reads.size }
        // 2 Hz each, every one of them: at most one read apart.
        assertTrue(counts.max() - counts.min() <= 1, "uneven reads: ${counts.min()}..${counts.max()}")
        assertTrue(counts.min() in 38..41, "reads of each in 20 s: ${counts.min()}")
        // Said once, with the rate it sustains: a read of each every 500 ms.
        assertEquals(1, run.warnings.size, "warnings: ${run.warnings}")
        val (members, achieved) = run.warnings.single()
        assertEquals(1000, members)
        assertTrue(achieved in 480.milliseconds..520.milliseconds, "achieved $achieved")
        // What was due (200 ticks of each) and not read counts as missed.
        assertTrue(run.missed in 155_000L..162_000L, "missed ${run.missed}")
    }

    @Test
    fun `a component whose read hangs is passed over without holding the others up`() = runTest {
        var missed = 0L
        val reads = CoroutineScope(coroutineContext + Job())
        val schedule =
            PollSchedule(backgroundScope, 100.milliseconds, 8, { missed += it }, { _, _ -> }, testScheduler.timeSource)
        val hung =
            object : PollSchedule.Member {
                var ticks = 0

                override fun tick(done: () -> Unit) {
                    ticks++
                }
            }
        val healthy = List(9) { Component(reads, 1.milliseconds) { testScheduler.currentTime } }
        schedule.add(hung)
        healthy.forEach(schedule::add)
        testScheduler.advanceTimeBy(5.seconds)
        schedule.stop()
        reads.coroutineContext[Job]!!.cancel()

        assertEquals(1, hung.ticks)
        healthy.forEach { assertTrue(it.reads.size in 49..50, "reads: ${it.reads.size}") }
        assertTrue(missed in 48L..50L, "missed $missed")
    }

    /**
     * A component read by probes answered after [replyTime]; a probe left unanswered is [late] once its turn comes
     * again.
     */
    private class Probed(
        private val scope: CoroutineScope,
        private val replyTime: Duration?,
        private val clock: () -> Long,
    ) : PollSchedule.Member {
        val probes = mutableListOf<Long>()
        var ticks = 0
        var lates = 0
        private var pending: (() -> Unit)? = null

        override fun probe(done: () -> Unit): Boolean {
            probes += clock()
            pending = done
            replyTime?.let {
                scope.launch {
                    delay(it)
                    done()
                }
            }
            return true
        }

        override fun tick(done: () -> Unit) {
            ticks++
            done()
        }

        override fun late() {
            lates++
            // Given up to the monitor, whose own read ends it.
            pending?.invoke()
        }
    }

    @Test
    fun `probes hold no read in flight and a probe still unanswered at its next turn is late`() = runTest {
        var missed = 0L
        val replies = CoroutineScope(coroutineContext + Job())
        // One tick in flight at a time, and replies take a quarter of a period: ticks could serve 40 components
        // a second, probes (25 pending at a time) every one of the 100 ten times a second.
        val schedule =
            PollSchedule(backgroundScope, 100.milliseconds, 1, { missed += it }, { _, _ -> }, testScheduler.timeSource)
        val answering = List(99) { Probed(replies, 25.milliseconds) { testScheduler.currentTime } }
        val silent = Probed(replies, null) { testScheduler.currentTime }
        answering.forEach(schedule::add)
        schedule.add(silent)
        testScheduler.advanceTimeBy(10.seconds)
        schedule.stop()
        replies.coroutineContext[Job]!!.cancel()

        answering.forEach {
            assertTrue(it.probes.size in 99..100, "probes: ${it.probes.size}")
            assertEquals(0, it.lates)
            assertEquals(0, it.ticks)
        }
        // Probed, passed over as late the next round (its read handed over, and ended), probed again.
        assertTrue(silent.probes.size in 49..50, "probes: ${silent.probes.size}")
        assertTrue(silent.lates in silent.probes.size - 1..silent.probes.size + 1, "lates: ${silent.lates}")
        assertTrue(missed in 49L..50L, "missed $missed")
    }
}
