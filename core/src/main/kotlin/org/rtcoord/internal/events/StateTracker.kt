package org.rtcoord.internal.events

import org.rtcoord.LifeCycle
import org.rtcoord.internal.events.ContextPhase.Agreed
import org.rtcoord.internal.events.ContextPhase.Disagreeing
import org.rtcoord.internal.events.ContextPhase.Held
import org.rtcoord.internal.events.ContextPhase.Leading

/**
 * The lifecycle of one component in one execution context, reconciled from two sources: the states its observer hints
 * report, in order, and the state read back from it. Hints are untrusted: a hinted transition is published only once a
 * read agrees with where the hints lead. A read that finds a change no hint announced yet waits for the hints too, when
 * hints are expected: they may be on their way, and arriving after the change was published they would announce it a
 * second time. What the two sources do not agree on within the grace period, counted from the first read that
 * disagreed, is decided by the read. So the published stream has no phantom transition, keeps every transition the
 * hints reported and the reads confirmed, and always ends in the real state.
 *
 * A hinted deactivation (ACTIVE to INACTIVE) that a read confirms is held until [settleMillis] after its INACTIVE hint
 * came and a marker sent after that read came back ([flushed]), or [holdLimitMillis] after the hint at most: an abort
 * hints INACTIVE then ERROR, and when a reset follows at once, a read that overtook the ERROR hint finds INACTIVE too.
 * The ERROR hint arriving meanwhile turns the pair into the abort it was. The ERROR hint was sent before the read
 * answered, so it is in this host's socket when the read's answer is; the marker is sent once the ORB has taken it, and
 * comes back after it.
 *
 * Where it stands is its [phase]: see [ContextPhase], and the table in [ComponentWatch]'s KDoc.
 */
internal class StateTracker(
    initial: LifeCycle,
    private val holdLimitMillis: Long = 0,
    private val settleMillis: Long = 0,
) {
    /** A hinted state, and when its hint came: a held deactivation counts from its INACTIVE hint's arrival. */
    private class Hinted(val state: LifeCycle, val at: Long)

    /** The last published state. */
    var confirmed: LifeCycle = initial
        private set

    /** Where the hints lead from [confirmed], in order. */
    private val hinted = ArrayList<Hinted>()

    /** Where the reconciliation stands. */
    var phase: ContextPhase = Agreed
        private set

    /** Every hint sent before the latest marker has been taken: a held deactivation, once settled, need not wait. */
    fun flushed() {
        (phase as? Held)?.let { phase = it.copy(flushed = true) }
    }

    /**
     * Takes a state hinted by a hint that came at [at]; duplicates and impossible transitions are ignored (the next
     * read decides).
     */
    fun hint(state: LifeCycle, at: Long) {
        val last = hinted.lastOrNull()?.state ?: confirmed
        if (state == last || !possible(last, state)) return
        hinted += Hinted(state, at)
        phase =
            when (val current = phase) {
                // What the read found unannounced may be what this hint announces: the hints lead now.
                is Disagreeing -> Leading(current.since)
                // Another deactivation: the marker that flushed the first says nothing of the hints sent after it.
                is Held ->
                    if (last == LifeCycle.ACTIVE && state == LifeCycle.INACTIVE) current.copy(flushed = false)
                    else current
                else -> current
            }
    }

    /**
     * Reconciles with [real], read just now, and returns the transitions to publish. [hintsExpected] says whether an
     * observer announces this component's changes.
     */
    fun reconcile(
        real: LifeCycle,
        now: Long,
        graceMillis: Long,
        hintsExpected: Boolean,
    ): List<Pair<LifeCycle, LifeCycle>> {
        if (real == LifeCycle.UNKNOWN) return emptyList()
        val leads = hinted.lastOrNull()
        val agreed = if (leads == null) real == confirmed || !hintsExpected else leads.state == real
        if (!agreed) {
            val since = (phase as? ContextPhase.Unconfirmed)?.since ?: now
            phase = if (leads == null) Disagreeing(since) else Leading(since)
            if (now - since < graceMillis) return emptyList()
        }
        val hintedPath = leads?.state == real
        val path = if (hintedPath) listOf(confirmed) + hinted.map { it.state } else listOf(confirmed, real)
        if (hintedPath && hintsExpected && path.takeLast(2) == listOf(LifeCycle.ACTIVE, LifeCycle.INACTIVE)) {
            val held = phase as? Held ?: Held(leads.at, flushed = false)
            phase = held
            val settled = held.flushed && now - held.since >= settleMillis
            if (!settled && now - held.since < holdLimitMillis) return emptyList()
        }
        phase = Agreed
        hinted.clear()
        confirmed = real
        return collapseAborts(path).zipWithNext().filter { (from, to) -> from != to }
    }

    private companion object {
        /** OpenRTM's transitions; anything else in a hint is noise. */
        fun possible(from: LifeCycle, to: LifeCycle): Boolean =
            when (from) {
                LifeCycle.CREATED -> to == LifeCycle.INACTIVE
                LifeCycle.INACTIVE -> to == LifeCycle.ACTIVE || to == LifeCycle.ERROR
                LifeCycle.ACTIVE -> to == LifeCycle.INACTIVE || to == LifeCycle.ERROR
                LifeCycle.ERROR -> to == LifeCycle.INACTIVE
                LifeCycle.UNKNOWN -> to != LifeCycle.UNKNOWN
            }

        /** A component aborting from ACTIVE announces INACTIVE then ERROR; it was never INACTIVE in between. */
        fun collapseAborts(path: List<LifeCycle>): List<LifeCycle> = path.filterIndexed { index, state ->
            !(state == LifeCycle.INACTIVE &&
                path.getOrNull(index - 1) == LifeCycle.ACTIVE &&
                path.getOrNull(index + 1) == LifeCycle.ERROR)
        }
    }
}
