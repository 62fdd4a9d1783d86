package org.rtcoord.internal

import org.rtcoord.LifeCycle

/** This state as the API says it: [LifeCycle.UNKNOWN] for a value OpenRTM-aist does not define. */
internal fun RTC.LifeCycleState.toLifeCycle(): LifeCycle =
    when (value()) {
        RTC.LifeCycleState._CREATED_STATE -> LifeCycle.CREATED
        RTC.LifeCycleState._INACTIVE_STATE -> LifeCycle.INACTIVE
        RTC.LifeCycleState._ACTIVE_STATE -> LifeCycle.ACTIVE
        RTC.LifeCycleState._ERROR_STATE -> LifeCycle.ERROR
        else -> LifeCycle.UNKNOWN
    }
