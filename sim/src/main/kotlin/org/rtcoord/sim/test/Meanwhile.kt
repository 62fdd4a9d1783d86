package org.rtcoord.sim.test

import kotlin.time.Duration

/**
 * The receiver of `meanwhile { }`: faults applied at their times from the scenario's start, alongside its steps,
 * whatever step the timeline is waiting on (an `at` written among the steps waits for the steps before it). How
 * `rtcoord test --explore` applies a schedule, and how a test it finds is written.
 */
@TestDsl
public class Meanwhile internal constructor(private val fileName: String) {
    internal val faults = mutableListOf<TestStep.At>()

    /** At [time] after the coordinator started, does what [faults] says to the system. */
    public fun at(time: Duration, faults: Faults.() -> Unit) {
        this.faults +=
            TestStep.At(Throwable().stackTrace.firstOrNull { it.fileName == fileName }?.lineNumber ?: 0, time, faults)
    }
}
