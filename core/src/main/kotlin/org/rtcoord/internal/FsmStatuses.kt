package org.rtcoord.internal

import org.rtcoord.FsmStatus
import org.rtcoord.FsmStatusImpl
import org.rtcoord.ObserverFlavour
import org.rtcoord.WatchMethod

/** The repository id of FSM4RTC's `ExtendedFsmService`, which an FSM component offers as an SDO service. */
internal const val FSM_SERVICE_ID = "IDL:omg.org/RTC/ExtendedFsmService:1.0"

/** Why the state of a component watched by [method] (null: not watched) is not known. */
internal fun unknownFsmStatus(method: WatchMethod?): FsmStatus =
    FsmStatusImpl(
        null,
        when (method) {
            is WatchMethod.Pushed ->
                when (method.flavour) {
                    ObserverFlavour.OMG -> "not told yet: OpenRTM-aist tells the state only when it changes"
                    ObserverFlavour.OPENRTM -> "its observer, ${method.flavour.label}, carries no FSM status"
                }
            is WatchMethod.Polled -> "polled: OpenRTM-aist tells the state only to FSM4RTC observers"
            is WatchMethod.Unwatched,
            null -> "not watched: OpenRTM-aist tells the state only to FSM4RTC observers, as it changes"
        },
    )
