package org.rtcoord.sim.test

import kotlin.time.ComparableTimeMark
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.flow.first
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.HandlerFailure
import org.rtcoord.sim.SimulatedSystem

/**
 * Plays a scenario's steps in order against a started [coordinator] on [system], from [origin] (the coordinator's
 * start): injects the faults of `at` steps, waits for each expectation, and begins each invariant with the [observer].
 * [play] stops at the first step that fails and returns its failure; [endChecks] are the checks made once every step is
 * done.
 */
internal class ScenarioPlayer(
    private val system: SimulatedSystem,
    private val coordinator: Coordinator,
    private val reads: SystemReads,
    private val observer: ScenarioObserver,
    private val source: TestSource,
    private val origin: ComparableTimeMark,
    private val clock: ScenarioClock,
) {
    /** Plays [steps]; the failure of the first that fails, or null. */
    suspend fun play(steps: List<TestStep>): TestFailure? {
        for (step in steps) {
            // Its faults are applied alongside the steps, from the scenario's start (ScenarioRun).
            if (step is TestStep.Meanwhile) continue
            val failure =
                when (step) {
                    is TestStep.At -> at(step)
                    is TestStep.Expect -> expect(step)
                    is TestStep.ExpectMode -> expectMode(step)
                    is TestStep.ExpectLog -> expectLog(step)
                    is TestStep.ExpectHandlerFailure -> expectHandlerFailure(step)
                    is TestStep.Invariant -> null.also { observer.begin(step) }
                    is TestStep.NoRestarts,
                    is TestStep.Meanwhile -> null
                }
            observer.step("${source.at(step)} ${if (failure == null) "held" else "failed"}")
            if (failure != null) return failure
        }
        return null
    }

    /** What is checked once the timeline is done: that no supervisor restarted what [steps] say it must not. */
    fun endChecks(steps: List<TestStep>): List<TestFailure> {
        // Counted by the supervisors themselves: every restart, however close together.
        val restarts = coordinator.supervision.flatMap { it.status.value.restartsByChild.entries }
        return steps.filterIsInstance<TestStep.NoRestarts>().mapNotNull { step ->
            val times =
                restarts
                    .filter { it.key.substringAfterLast('/').removeSuffix(".rtc") == step.component }
                    .sumOf { it.value }
            if (times == 0) null
            else
                TestFailure(
                    source.at(step),
                    "expected no restarts of ${step.component}, but a supervisor restarted it $times time(s)",
                )
        }
    }

    private suspend fun at(step: TestStep.At): TestFailure? {
        clock.delay(step.time - origin.elapsedNow())
        return try {
            step.faults(SimFaults(system, observer::fault))
            null
        } catch (e: CancellationException) {
            throw e
        } catch (e: Exception) {
            TestFailure(source.at(step), "at ${step.time}: ${e.message ?: e.javaClass.simpleName}")
        }
    }

    private suspend fun expect(step: TestStep.Expect): TestFailure? {
        var last = RecordedObservation(reads)
        var thrown: Exception? = null
        val held =
            holdsWithin(step.within) {
                last = RecordedObservation(reads)
                thrown = null
                try {
                    step.condition(last)
                } catch (e: CancellationException) {
                    throw e
                } catch (e: Exception) {
                    thrown = e
                    false
                }
            }
        if (held) return null
        val threw = thrown?.let { listOf("the condition threw ${it.javaClass.simpleName}: ${it.message}") }.orEmpty()
        return TestFailure(
            source.at(step),
            "expected ${source.condition(step)} within ${step.within}, but it did not hold",
            last.readings.map(Reading::toString) + threw,
        )
    }

    private suspend fun expectMode(step: TestStep.ExpectMode): TestFailure? {
        val machine = coordinator.machine(step.machine)
        if (holdsWithin(step.within) { isIn(machine.mode.value, step.machine, step.mode) }) return null
        val now = machine.mode.value
        return TestFailure(
            source.at(step),
            "expected mode machine ${step.machine} in mode ${step.mode} within ${step.within}, but it was " +
                (now?.removePrefix("${step.machine}/")?.let { "in $it" } ?: "in no mode yet"),
            machine.history.value.map { "${it.from ?: "(start)"} -> ${it.to} on ${it.trigger}" },
        )
    }

    private suspend fun expectLog(step: TestStep.ExpectLog): TestFailure? {
        if (holdsWithin(step.within) { reads.log.any { step.text in it } }) return null
        val logged = reads.log
        return TestFailure(
            source.at(step),
            "expected a log line containing '${step.text}' within ${step.within}, but none came",
            listOf(
                "the coordinator logged ${logged.size} lines${logged.lastOrNull()?.let { ", the last: $it" }.orEmpty()}"
            ),
        )
    }

    private suspend fun expectHandlerFailure(step: TestStep.ExpectHandlerFailure): TestFailure? {
        if (holdsWithin(step.within) { coordinator.handlerFailures.any { step.text in it.toString() } }) return null
        val failed = coordinator.handlerFailures
        return TestFailure(
            source.at(step),
            "expected a handler failure containing '${step.text}' within ${step.within}, but ${if (failed.isEmpty()) "no handler failed" else "none matched"}",
            failed.map(HandlerFailure::toString),
        )
    }

    /**
     * Whether [check] holds within [within]: read now, again after each entry of the scenario's timeline (at least
     * every [POLL]), and once more at the deadline.
     */
    private suspend fun holdsWithin(within: Duration, check: suspend () -> Boolean): Boolean {
        val deadline = clock.markNow() + within
        while (true) {
            val seen = observer.changes.value
            if (check()) return true
            val left = -deadline.elapsedNow()
            if (!left.isPositive()) return false
            clock.withTimeoutOrNull(minOf(left, POLL)) { observer.changes.first { it != seen } }
        }
    }

    private companion object {
        val POLL = 50.milliseconds

        /**
         * Whether [active], the machine's mode path, is [mode]: a path below [machine], or a mode's name anywhere on
         * it.
         */
        fun isIn(active: String?, machine: String, mode: String): Boolean {
            val below = active?.removePrefix("$machine/") ?: return false
            return below == mode || below.startsWith("$mode/") || ('/' !in mode && mode in below.split('/'))
        }
    }
}
