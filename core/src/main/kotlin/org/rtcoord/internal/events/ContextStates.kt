package org.rtcoord.internal.events

import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle
import org.rtcoord.StateChanged

/**
 * One watched component's lifecycle in each of its execution contexts: a [StateTracker] per context
 * handle, fed the lifecycle hints and the reads, and the [StateChanged] events they agree on.
 */
internal class ContextStates(private val node: ComponentNode, private val holdLimitMillis: Long, private val settleMillis: Long) {
    private val trackers = HashMap<Int, StateTracker>()

    /** The state in each context as the published events tell it, by handle. */
    val published: Map<Int, LifeCycle> get() = trackers.mapValues { it.value.confirmed }

    /** Whether hints and reads disagree somewhere, and a read after the grace period must decide. */
    val awaitingConfirmation: Boolean get() = trackers.values.any { it.awaitingConfirmation }

    /** When the oldest disagreement between hints and reads began; null when none is awaiting confirmation. */
    val disagreedSince: Long? get() = trackers.values.mapNotNull { it.disagreedSince }.minOrNull()

    /** Whether, somewhere, hints lead to a state the last read did not find yet. */
    val hintsLead: Boolean get() = trackers.values.any { it.hintsLead }

    /** Whether a hinted deactivation is held somewhere, until it settled and [flushed], or the hold limit. */
    val holding: Boolean get() = trackers.values.any { it.holding }

    /** How long after [now] the first held deactivation has settled (0 if it has); null when none is held. */
    fun settlesIn(now: Long): Long? = trackers.values.mapNotNull { it.settlesIn(now) }.minOrNull()

    /** Whether a possible deactivation was hinted and is not published yet. */
    val deactivationPending: Boolean get() = trackers.values.any { it.deactivationPending }

    /** When the first held deactivation is published whatever else happens; null when none is held. */
    fun heldUntil(): Long? = trackers.values.mapNotNull { it.heldUntil() }.minOrNull()

    /** Whether a deactivation is held somewhere and the hints that may turn it into an abort are not known to be in: it wants a marker. */
    val awaitingHints: Boolean get() = trackers.values.any { it.awaitingHints }

    /** The hints sent before the latest marker have all been taken: possible deactivations end once settled. */
    fun flushed() {
        trackers.values.forEach(StateTracker::flushed)
    }

    /**
     * Takes an RTC_STATUS [hint] that came at [at]; returns the handle of the context whose state is
     * then worth reading, or null when the hint names no state or a context the component is not known to
     * be in: only reading the whole component tells what, if anything, happened.
     */
    fun hinted(hint: Hint, at: Long): Int? {
        val (state, handle) = hint.lifeCycle() ?: return null
        val tracker = trackers[handle] ?: return null
        tracker.hint(state, at)
        return handle
    }

    /** Reconciles each context's state in [snapshot] (read after [previous]) with the hints: the transitions to publish. */
    fun read(previous: ComponentSnapshot?, snapshot: ComponentSnapshot, now: Long, graceMillis: Long, hintsExpected: Boolean): List<StateChanged> {
        val events = mutableListOf<StateChanged>()
        for (context in snapshot.contexts) {
            val tracker = trackers.getOrPut(context.handle) { StateTracker(previous?.context(context.handle)?.state ?: context.state, holdLimitMillis, settleMillis) }
            tracker.reconcile(context.state, now, graceMillis, hintsExpected).forEach { (from, to) -> events += StateChanged(node, context.handle, from, to) }
        }
        trackers.keys.retainAll(snapshot.contexts.map { it.handle }.toSet())
        return events
    }
}
