package org.rtcoord.sim.explore

import org.rtcoord.sim.test.ScenarioPlan
import org.rtcoord.sim.test.ScheduledFault

/**
 * The faults one run of an exploration applies to [scenario], in time order: run [index] of [seed]'s sequence, which
 * draws it again the same ([ScheduleSpace.draw]), or a smaller one shrinking made of it.
 */
internal class Schedule(val seed: Long, val index: Long, val scenario: ScenarioPlan, faults: List<ScheduledFault>) {
    val faults: List<ScheduledFault> = faults.sortedBy { it.time }

    /** `SEED:INDEX`, what `--replay` takes. */
    val key: String
        get() = "$seed:$index"

    /** The components and managers its faults are on. */
    val targets: Set<String>
        get() = faults.mapNotNull { it.fault.target }.toSet()

    /** The same run with [faults] instead. */
    fun with(faults: List<ScheduledFault>): Schedule = Schedule(seed, index, scenario, faults)

    /** `1.230 s fail laser0, 3.400 s killManager localisation`, or `no faults`. */
    override fun toString(): String = faults.joinToString(", ").ifEmpty { "no faults" }
}
