package org.rtcoord.sim.explore

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import org.rtcoord.sim.test.ScheduledFault

/**
 * Makes a failing schedule smaller while it [still fails][stillFails] the same way, as Hypothesis and QuickCheck shrink
 * a failing input, in this order: fewer faults (each left out in turn, the last first), fewer components (a fault moved
 * onto a target another fault of the schedule has), then earlier and rounder times (each moved as early as the fault
 * before it, or rounded down to the second, the half second, the tenth). At most [budget] runs: what was smallest by
 * then is the answer.
 */
internal class ScheduleShrinker(private val budget: Int, private val stillFails: suspend (Schedule) -> Boolean) {
    /** How many runs shrinking took. */
    var runs: Int = 0
        private set

    suspend fun shrink(failing: Schedule): Schedule {
        var smallest = failing
        suspend fun tryIt(candidate: Schedule): Boolean {
            if (runs >= budget || candidate.faults == smallest.faults) return false
            runs++
            return stillFails(candidate).also { if (it) smallest = candidate }
        }
        for (i in failing.faults.indices.reversed()) {
            if (i < smallest.faults.size) tryIt(smallest.with(smallest.faults.filterIndexed { j, _ -> j != i }))
        }
        for (i in smallest.faults.indices) {
            val fault = smallest.faults[i]
            val target = fault.fault.target ?: continue
            if (smallest.faults.count { it.fault.target == target } > 1) continue
            val others =
                smallest.faults
                    .mapNotNull { it.fault.target }
                    .filter { it != target && sameKind(smallest, it, fault) }
                    .distinct()
            for (other in others) if (
                tryIt(smallest.with(smallest.faults.replace(i, ScheduledFault(fault.time, fault.fault.on(other)))))
            )
                break
        }
        for (i in smallest.faults.indices) {
            val fault = smallest.faults[i]
            val floor = if (i == 0) Duration.ZERO else smallest.faults[i - 1].time
            val earlier =
                (listOf(floor) + ROUNDINGS.map { round(fault.time, it) })
                    .filter { it >= floor && it < fault.time }
                    .distinct()
            for (time in earlier) if (
                tryIt(smallest.with(smallest.faults.replace(i, ScheduledFault(time, fault.fault))))
            )
                break
        }
        return smallest
    }

    /**
     * Whether [target] is what [fault]'s kind is on: a component for a component's fault, a manager for a manager's.
     */
    private fun sameKind(schedule: Schedule, target: String, fault: ScheduledFault): Boolean =
        schedule.faults.any { it.fault.target == target && it.fault.kind.on == fault.fault.kind.on }

    private fun List<ScheduledFault>.replace(i: Int, with: ScheduledFault): List<ScheduledFault> = mapIndexed { j, it ->
        if (j == i) with else it
    }

    private companion object {
        val ROUNDINGS = listOf(1.seconds, 500.milliseconds, 100.milliseconds)

        fun round(time: Duration, to: Duration): Duration =
            to * (time.inWholeMilliseconds / to.inWholeMilliseconds).toInt()
    }
}
