package org.rtcoord.internal.events

import org.rtcoord.LifeCycle

/**
 * The lifecycle of one component in one execution context, reconciled from two sources: the states
 * its observer hints report, in order, and the state read back from it. Hints are untrusted: a hinted
 * transition is published only once a read agrees with where the hints lead; hints a read never
 * confirms within the grace period are dropped, and the read state wins. So the published stream has
 * no phantom transition, keeps every transition the hints reported and the reads confirmed, and always
 * ends in the real state.
 */
internal class StateTracker(initial: LifeCycle) {
    /** The last published state. */
    var confirmed: LifeCycle = initial
        private set

    private val hinted = ArrayList<LifeCycle>()
    private var hintedSince = 0L

    /** Whether hints wait for a read to confirm them. */
    val awaitingConfirmation: Boolean get() = hinted.isNotEmpty()

    /** Takes a hinted state; duplicates and impossible transitions are ignored (the next read decides). */
    fun hint(state: LifeCycle, now: Long) {
        val last = hinted.lastOrNull() ?: confirmed
        if (state == last || !possible(last, state)) return
        if (hinted.isEmpty()) hintedSince = now
        hinted += state
    }

    /**
     * Reconciles with [real], read just now, and returns the transitions to publish. Unconfirmed hints
     * older than [graceMillis] are given up.
     */
    fun reconcile(real: LifeCycle, now: Long, graceMillis: Long): List<Pair<LifeCycle, LifeCycle>> {
        if (real == LifeCycle.UNKNOWN) return emptyList()
        val path = when {
            hinted.lastOrNull() == real -> listOf(confirmed) + hinted
            hinted.isNotEmpty() && now - hintedSince < graceMillis -> return emptyList()
            else -> listOf(confirmed, real)
        }
        hinted.clear()
        confirmed = real
        return collapseAborts(path).zipWithNext().filter { (from, to) -> from != to }
    }

    private companion object {
        /** OpenRTM's transitions; anything else in a hint is noise. */
        fun possible(from: LifeCycle, to: LifeCycle): Boolean = when (from) {
            LifeCycle.CREATED -> to == LifeCycle.INACTIVE
            LifeCycle.INACTIVE -> to == LifeCycle.ACTIVE || to == LifeCycle.ERROR
            LifeCycle.ACTIVE -> to == LifeCycle.INACTIVE || to == LifeCycle.ERROR
            LifeCycle.ERROR -> to == LifeCycle.INACTIVE
            LifeCycle.UNKNOWN -> to != LifeCycle.UNKNOWN
        }

        /** A component aborting from ACTIVE announces INACTIVE then ERROR; it was never INACTIVE in between. */
        fun collapseAborts(path: List<LifeCycle>): List<LifeCycle> = path.filterIndexed { index, state ->
            !(state == LifeCycle.INACTIVE && path.getOrNull(index - 1) == LifeCycle.ACTIVE && path.getOrNull(index + 1) == LifeCycle.ERROR)
        }
    }
}
