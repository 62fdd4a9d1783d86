package org.rtcoord.internal.events

import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle
import org.rtcoord.StateChanged
import org.rtcoord.internal.HandleMap

/**
 * One watched component's lifecycle in each of its execution contexts: a [StateTracker] per context handle, fed the
 * lifecycle hints and the reads, and the [StateChanged] events they agree on.
 */
internal class ContextStates(
    private val node: ComponentNode,
    private val holdLimitMillis: Long,
    private val settleMillis: Long,
) {
    private val trackers = HandleMap<StateTracker>()

    /** The state in each context as the published events tell it, by handle. */
    val published: Map<Int, LifeCycle>
        // A list's toMap() makes a map of one entry for the common component of one context: the model keeps it.
        get() =
            ArrayList<Pair<Int, LifeCycle>>(trackers.size)
                .apply { trackers.forEach { handle, tracker -> add(handle to tracker.confirmed) } }
                .toMap()

    /** When the oldest disagreement between hints and reads began; null when they agree in every context. */
    val disagreedSince: Long?
        get() = trackers.values().mapNotNull { (it.phase as? ContextPhase.Unconfirmed)?.since }.minOrNull()

    /** Whether, somewhere, hints lead to a state the reads have not found yet. */
    val hintsLead: Boolean
        get() = trackers.values().any { it.phase is ContextPhase.Leading }

    /** The deactivations held, one per context that holds one. */
    val held: List<ContextPhase.Held>
        get() = trackers.values().mapNotNull { it.phase as? ContextPhase.Held }

    /** Whether hints and reads agree in every context, and nothing is held. */
    val agreed: Boolean
        get() = trackers.values().all { it.phase == ContextPhase.Agreed }

    /** The hints sent before the latest marker have all been taken: held deactivations end once settled. */
    fun flushed() {
        trackers.values().forEach(StateTracker::flushed)
    }

    /**
     * Takes an RTC_STATUS [hint] that came at [at]; returns the handle of the context whose state is then worth
     * reading, or null when the hint names no state or a context the component is not known to be in: only reading the
     * whole component tells what, if anything, happened.
     */
    fun hinted(hint: Hint, at: Long): Int? {
        val (state, handle) = hint.lifeCycle() ?: return null
        val tracker = trackers[handle] ?: return null
        tracker.hint(state, at)
        return handle
    }

    /**
     * Reconciles each context's state in [snapshot] (read after [previous]) with the hints: the transitions to publish.
     */
    fun read(
        previous: ComponentSnapshot?,
        snapshot: ComponentSnapshot,
        now: Long,
        graceMillis: Long,
        hintsExpected: Boolean,
    ): List<StateChanged> {
        val events = mutableListOf<StateChanged>()
        for (context in snapshot.contexts) {
            val tracker =
                trackers.getOrPut(context.handle) {
                    StateTracker(
                        previous?.context(context.handle)?.state ?: context.state,
                        holdLimitMillis,
                        settleMillis,
                    )
                }
            tracker.reconcile(context.state, now, graceMillis, hintsExpected).forEach { (from, to) ->
                events += StateChanged(node, context.handle, from, to)
            }
        }
        trackers.retain { handle -> snapshot.contexts.any { it.handle == handle } }
        return events
    }
}
