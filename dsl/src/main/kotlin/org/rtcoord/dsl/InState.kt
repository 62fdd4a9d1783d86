package org.rtcoord.dsl

import java.util.concurrent.ConcurrentHashMap
import org.rtcoord.ComponentNode
import org.rtcoord.LifeCycle
import org.rtcoord.Node
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.StateChanged

/**
 * Follows whether each component watched is in [state], for a rule on being in it or entering it: one firing per stay.
 * The read that finds a component already in [state] is made when its events start to reach the rule, and may come
 * after changes whose events are still on their way: the event of the entry that read found is then not a second entry,
 * and is dropped.
 */
internal class InState(private val state: LifeCycle) : EventReading<StateChanged> {
    /** Whether the component was last known in [state], by component path and context handle. */
    private val inState = ConcurrentHashMap<Pair<String, Int>, Boolean>()

    /** A component already in [state] in its default context: a [StateChanged] from [state] to itself. */
    override suspend fun prepare(node: Node): StateChanged? {
        if (node !is ComponentNode) return null
        val now =
            try {
                node.state()
            } catch (e: RtcException) {
                // Judged from its first event instead.
                return null
            }
        inState[node.path.toString() to DEFAULT_HANDLE] = now == state
        return if (now == state) StateChanged(node, DEFAULT_HANDLE, now, now) else null
    }

    /** [event] when it enters [state] in a context not known to be in it already; null otherwise. */
    override fun translate(event: RtcEvent): StateChanged? {
        if (event !is StateChanged) return null
        val entered = event.new == state
        val already = inState.put(event.source.path.toString() to event.handle, entered) ?: false
        return event.takeIf { entered && !already }
    }

    private companion object {
        /** The handle of the context [ComponentNode.state] reads by default. */
        const val DEFAULT_HANDLE = 0
    }
}
