package org.rtcoord.sim.test

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * The words of a test's timeline, at the top of a test file (steps every scenario starts with) and in each
 * [scenario][CoordinatorTest.scenario]. Steps run in the order written from the moment the coordinator has started;
 * each remembers the line of the test file it is written on, which its failure names.
 */
@TestDsl
public abstract class Timeline
internal constructor(
    /** The test file's name, which the steps' lines are looked up in. */
    internal val fileName: String
) {
    internal val steps = mutableListOf<TestStep>()

    /** At [time] after the coordinator started (at once if that is past), does what [faults] says to the system. */
    public fun at(time: Duration, faults: Faults.() -> Unit) {
        steps += TestStep.At(line(), time, faults)
    }

    /**
     * Applies the faults of [faults]' `at(...) { }` steps at their times from the coordinator's start, alongside the
     * steps of the scenario wherever this is written, whatever step the timeline is waiting on; the scenario lasts at
     * least until the last is applied. `rtcoord test --explore` applies the schedules it draws this way, and writes the
     * tests it finds with it.
     */
    public fun meanwhile(faults: Meanwhile.() -> Unit) {
        steps += TestStep.Meanwhile(line(), Meanwhile(fileName).apply(faults).faults.toList())
    }

    /**
     * Expects [condition] to hold within [within] from here in the timeline. It is read again on every event of the
     * system and the coordinator, and at least every 50 ms; a failure shows what each read of it returned at the
     * deadline.
     */
    public fun expect(within: Duration = DEFAULT_WITHIN, condition: suspend Observation.() -> Boolean) {
        steps += TestStep.Expect(line(), within, condition)
    }

    /**
     * Expects the coordinator's mode machine [machine] to be in [mode] within [within]: a path below the machine
     * (`degraded/odometry`) or one mode's name (`odometry`); a machine in a nested mode is in each mode that contains
     * it. A machine or mode the coordinator does not declare fails the test when it is loaded.
     */
    public fun expectMode(machine: String, mode: String, within: Duration = DEFAULT_WITHIN) {
        steps += TestStep.ExpectMode(line(), machine, mode, within)
    }

    /** Expects the coordinator to log a line containing [text] within [within]. */
    public fun expectLog(text: String, within: Duration = DEFAULT_WITHIN) {
        steps += TestStep.ExpectLog(line(), text, within)
    }

    /**
     * Expects a handler of the coordinator to fail, with [text] in its line (`rule '...' failed at FILE:LINE: TYPE:
     * MESSAGE`), within [within]. Any handler failure fails the test unless the scenario expects one whose line
     * contains its text, wherever in the scenario this is written.
     */
    public fun expectHandlerFailure(text: String, within: Duration = DEFAULT_WITHIN) {
        steps += TestStep.ExpectHandlerFailure(line(), text, within)
    }

    /**
     * Expects no supervisor of the coordinator to restart [component] (`laser0` or `laser0.rtc`): checked when the
     * timeline ends.
     */
    public fun expectNoRestartsOf(component: String) {
        steps += TestStep.NoRestarts(line(), component.removeSuffix(".rtc"))
    }

    /**
     * [condition] holds from here to the end of the scenario: it is read when the timeline gets here and again on every
     * event of the system and the coordinator (not by polling), and the test fails at the first event after which it
     * does not hold, naming the event and its time.
     */
    public fun always(condition: suspend Observation.() -> Boolean) {
        steps += TestStep.Invariant(line(), TestStep.Invariant.Kind.ALWAYS, condition)
    }

    /** [condition] never holds from here to the end of the scenario: read as [always] reads its condition. */
    public fun never(condition: suspend Observation.() -> Boolean) {
        steps += TestStep.Invariant(line(), TestStep.Invariant.Kind.NEVER, condition)
    }

    /** The line of the test file the calling step is written on. */
    internal fun line(): Int = Throwable().stackTrace.firstOrNull { it.fileName == fileName }?.lineNumber ?: 0

    private companion object {
        val DEFAULT_WITHIN = 5.seconds
    }
}
