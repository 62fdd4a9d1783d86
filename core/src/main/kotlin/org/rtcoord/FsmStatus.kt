package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * What the tree knows of an FSM component's state machine (OpenRTM-aist 2.0's FSM4RTC): the state it
 * last entered, or why that is not known. OpenRTM-aist tells the state only to FSM4RTC observers, as
 * FSM_STATUS hints at each transition; its `ExtendedFsmService.get_current_state` answers nothing.
 */
public class FsmStatus internal constructor(
    /** The state the machine last entered (a leaf once a transition is done); null when not known. */
    public val state: String?,
    /** Why [state] is not known, in words for people; null when it is known. */
    public val unknownBecause: String?,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("state" to state, "unknownBecause" to unknownBecause)

    internal companion object {
        /** The repository id of FSM4RTC's `ExtendedFsmService`, which an FSM component offers as an SDO service. */
        const val SERVICE_ID = "IDL:omg.org/RTC/ExtendedFsmService:1.0"

        /** Why the state of a component watched by [method] (null: not watched) is not known. */
        fun unknown(method: WatchMethod?): FsmStatus = FsmStatus(
            null,
            when (method) {
                is WatchMethod.Pushed -> when (method.flavour) {
                    ObserverFlavour.OMG -> "not told yet: OpenRTM-aist tells the state only when it changes"
                    ObserverFlavour.OPENRTM -> "its observer, ${method.flavour.label}, carries no FSM status"
                }
                is WatchMethod.Polled -> "polled: OpenRTM-aist tells the state only to FSM4RTC observers"
                is WatchMethod.Unwatched, null -> "not watched: OpenRTM-aist tells the state only to FSM4RTC observers, as it changes"
            },
        )
    }
}
