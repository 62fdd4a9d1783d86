package org.rtcoord.internal.events

import org.rtcoord.LifeCycle

/**
 * The lifecycle of one component in one execution context, reconciled from two sources: the states
 * its observer hints report, in order, and the state read back from it. Hints are untrusted: a hinted
 * transition is published only once a read agrees with where the hints lead. A read that finds a change
 * no hint announced yet waits for the hints too, when hints are expected: they may be on their way, and
 * arriving after the change was published they would announce it a second time. What the two sources do
 * not agree on within the grace period, counted from the first read that disagreed, is decided by the
 * read. So the published stream has no phantom transition, keeps every transition the hints reported and
 * the reads confirmed, and always ends in the real state.
 *
 * A hinted deactivation (ACTIVE to INACTIVE) that a read confirms is held until [settleMillis] after its
 * INACTIVE hint came and a marker sent after that read came back ([flushed]), or [holdLimitMillis] after
 * the hint at most: an abort hints INACTIVE then ERROR, and when a reset follows at once, a read that
 * overtook the ERROR hint finds INACTIVE too. The ERROR hint arriving meanwhile turns the pair into the
 * abort it was. The ERROR hint was sent before the read answered, so it is in this host's socket when
 * the read's answer is; the marker is sent once the ORB has taken it, and comes back after it.
 */
internal class StateTracker(initial: LifeCycle, private val holdLimitMillis: Long = 0, private val settleMillis: Long = 0) {
    /** The last published state. */
    var confirmed: LifeCycle = initial
        private set

    private val hinted = ArrayList<LifeCycle>()

    /** When the read that found hints and reads disagreeing was made; null while they agree. */
    var disagreedSince: Long? = null
        private set

    /** When the INACTIVE hint of a possible deactivation came; null when none is pending. */
    private var deactivationHintedAt: Long? = null
    private var heldSince: Long? = null
    private var flushed = false

    /** Whether hints and reads disagree, and a later read must decide. */
    val awaitingConfirmation: Boolean get() = disagreedSince != null

    /** Whether hints lead to a state the last read did not find yet. */
    val hintsLead: Boolean get() = hinted.isNotEmpty() && disagreedSince != null

    /** Whether a possible deactivation was hinted and is not published yet. */
    val deactivationPending: Boolean get() = deactivationHintedAt != null

    /** Whether a hinted deactivation is held, until it settled and [flushed], or the hold limit. */
    val holding: Boolean get() = heldSince != null

    /** How long after [now] the held deactivation has settled (0 if it has); null when none is held. */
    fun settlesIn(now: Long): Long? = heldSince?.let { (it + settleMillis - now).coerceAtLeast(0) }

    /** When the held deactivation is published whatever else happens; null when none is held. */
    fun heldUntil(): Long? = heldSince?.let { it + holdLimitMillis }

    /** Every hint sent before the latest possible deactivation's marker has been taken: once settled, it need not wait. */
    fun flushed() {
        if (deactivationHintedAt != null) flushed = true
    }

    /** Whether a deactivation is held and not [flushed] yet. */
    val awaitingHints: Boolean get() = holding && !flushed

    /** Takes a state hinted by a hint that came at [at]; duplicates and impossible transitions are ignored (the next read decides). */
    fun hint(state: LifeCycle, at: Long) {
        val last = hinted.lastOrNull() ?: confirmed
        if (state == last || !possible(last, state)) return
        if (state == LifeCycle.INACTIVE && last == LifeCycle.ACTIVE) {
            deactivationHintedAt = at
            flushed = false
        }
        hinted += state
    }

    /**
     * Reconciles with [real], read just now, and returns the transitions to publish. [hintsExpected]
     * says whether an observer announces this component's changes.
     */
    fun reconcile(real: LifeCycle, now: Long, graceMillis: Long, hintsExpected: Boolean): List<Pair<LifeCycle, LifeCycle>> {
        if (real == LifeCycle.UNKNOWN) return emptyList()
        val agreed = if (hinted.isEmpty()) real == confirmed || !hintsExpected else hinted.last() == real
        if (!agreed) {
            val since = disagreedSince ?: now.also { disagreedSince = it }
            if (now - since < graceMillis) return emptyList()
        }
        val hintedPath = hinted.lastOrNull() == real
        val path = if (hintedPath) listOf(confirmed) + hinted else listOf(confirmed, real)
        if (hintedPath && hintsExpected && path.takeLast(2) == listOf(LifeCycle.ACTIVE, LifeCycle.INACTIVE)) {
            val since = heldSince ?: (deactivationHintedAt ?: now).also { heldSince = it }
            val settled = flushed && now - since >= settleMillis
            if (!settled && now - since < holdLimitMillis) return emptyList()
        }
        heldSince = null
        deactivationHintedAt = null
        flushed = false
        hinted.clear()
        disagreedSince = null
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
