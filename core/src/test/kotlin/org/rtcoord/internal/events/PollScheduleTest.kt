package org.rtcoord.internal.events

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
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** The tree's poll schedule on virtual time: reads spread over the period, and even degradation when they cannot keep up. */
@OptIn(ExperimentalCoroutinesApi::class)
class PollScheduleTest {
    /** A component whose every read takes [readTime]; it records when each read started. */
    private class Component(private val scope: CoroutineScope, private val readTime: Duration, private val clock: () -> Long) : PollSchedule.Member {
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
        val schedule = PollSchedule(backgroundScope, period, inFlight, { missed += it }, { members, achieved -> warnings += members to achieved }, testScheduler.timeSource)
        val components = List(count) { Component(reads, readTime) { testScheduler.currentTime } }
        components.forEach(schedule::add)
        testScheduler.advanceTimeBy(window)
        schedule.stop()
        reads.coroutineContext[Job]!!.cancel()
        return Run(components, missed, warnings)
    }

    @Test
    fun `reads are spread over the period, each component once per tick, and none is missed`() = runTest {
        val run = poll(count = 100, period = 100.milliseconds, inFlight = 8, readTime = 2.milliseconds, window = 10.seconds)

        // 100 ticks of each in 10 s, give or take the one under way at the end.
        run.components.forEach { assertTrue(it.reads.size in 99..100, "reads: ${it.reads.size}") }
        // One read starts every millisecond: spread, never a burst of 100 at once.
        val starts = run.components.flatMap { it.reads }.sorted()
        val perMillisecond = starts.groupingBy { it }.eachCount().values.max()
        assertEquals(1, perMillisecond, "reads starting in the same millisecond")
        assertEquals(0, run.missed)
        assertEquals(emptyList<Pair<Int, Duration>>(), run.warnings)
    }

    @Test
    fun `when reads cannot keep up every component is read at the same lower rate and it is said once`() = runTest {
        // 1000 components at 10 Hz want 10,000 reads a second; 8 reads of 4 ms at once sustain 2000.
        val run = poll(count = 1000, period = 100.milliseconds, inFlight = 8, readTime = 4.milliseconds, window = 20.seconds)

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
        val schedule = PollSchedule(backgroundScope, 100.milliseconds, 8, { missed += it }, { _, _ -> }, testScheduler.timeSource)
        val hung = object : PollSchedule.Member {
            var ticks = 0
            override fun tick(done: () -> Unit) { ticks++ }
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
}
