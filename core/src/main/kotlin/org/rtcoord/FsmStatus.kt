package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * What the tree knows of an FSM component's state machine (OpenRTM-aist 2.0's FSM4RTC): the state it last entered, or
 * why that is not known. OpenRTM-aist tells the state only to FSM4RTC observers, as FSM_STATUS hints at each
 * transition; its `ExtendedFsmService.get_current_state` answers nothing. Only the tree makes one: the class is sealed
 * for the reason [Node] gives.
 */
public sealed class FsmStatus(
    /** The state the machine last entered (a leaf once a transition is done); null when not known. */
    public val state: String?,
    /** Why [state] is not known, in words for people; null when it is known. */
    public val unknownBecause: String?,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("state" to state, "unknownBecause" to unknownBecause)

    override fun toString(): String = "FsmStatus(${fields()})"
}

/** The [FsmStatus]es the tree makes. */
internal class FsmStatusImpl(state: String?, unknownBecause: String?) : FsmStatus(state, unknownBecause)
