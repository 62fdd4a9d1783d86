package org.rtcoord.sim.test

import kotlin.time.Duration

/**
 * Faults applied at [time] from the scenario's start, alongside its steps: those of a test's `meanwhile` ([at] the line
 * of its `at`), or one of a schedule exploring drew ([at] null). One of a schedule that cannot be applied (its
 * component is gone already) makes the run skipped, not failed.
 */
internal class Injection(val time: Duration, val at: String?, val faults: Faults.() -> Unit) {
    companion object {
        /** [fault] as a schedule's injection. */
        fun of(fault: ScheduledFault): Injection = Injection(fault.time, null) { fault.fault.applyTo(this) }
    }
}
