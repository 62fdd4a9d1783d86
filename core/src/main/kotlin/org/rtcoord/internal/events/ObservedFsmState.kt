package org.rtcoord.internal.events

import org.rtcoord.ComponentNode
import org.rtcoord.FsmStateChanged

/**
 * The state a component's FSM last entered, as its FSM4RTC observer told it since it was attached. Nothing reads it
 * back (OpenRTM-aist's `ExtendedFsmService` answers `""`), so the hints alone say it, in the order the one ORB thread
 * that takes them received them.
 */
internal class ObservedFsmState(private val node: ComponentNode) {
    @Volatile private var state: String? = null

    /** Forgets the state: an observer attached anew tells it afresh. */
    fun forget() {
        state = null
    }

    /** The change [hint] tells, or null when it tells of no state entered. */
    fun changedBy(hint: Hint): FsmStateChanged? {
        val entered = hint.fsmEntered() ?: return null
        return FsmStateChanged(node, state, entered).also { state = entered }
    }
}
