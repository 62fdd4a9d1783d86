package org.rtcoord.sim.explore

import org.rtcoord.sim.test.TestFailure
import org.rtcoord.sim.test.TestResult

/** How one run of a schedule ended, judged by the test's oracle. */
internal sealed class Verdict {
    /** Every expectation held, no invariant broke, no handler failed. */
    object Passed : Verdict() {
        override fun toString(): String = "PASS"
    }

    /** The first [failure] of [result]; runs failing at the same [key] are one distinct failure. */
    class Failed(val failure: TestFailure, val result: TestResult) : Verdict() {
        /** Where it failed: the invariant's or expectation's line of the test, the handler's of the coordinator. */
        val key: String
            get() = failure.at

        override fun toString(): String = "FAIL $failure"
    }

    /** A fault of the schedule could not be applied ([why]): not a failure, and not a pass. */
    class Skipped(val why: String) : Verdict() {
        override fun toString(): String = "SKIP $why"
    }

    /** Whether this is the same outcome as [other]: both passed, both skipped, or both failed at one place. */
    fun agrees(other: Verdict): Boolean =
        when (this) {
            is Passed -> other is Passed
            is Skipped -> other is Skipped
            is Failed -> other is Failed && other.key == key
        }

    companion object {
        fun of(result: TestResult): Verdict {
            val first = result.failures.firstOrNull() ?: return Passed
            return if (first.skipped) Skipped(first.message) else Failed(first, result)
        }
    }
}
