package org.rtcoord

/** A component's lifecycle state in one execution context. */
public enum class LifeCycle {
    CREATED, INACTIVE, ACTIVE, ERROR,

    /** The state could not be read. */
    UNKNOWN;

    internal companion object {
        fun of(state: RTC.LifeCycleState): LifeCycle = when (state.value()) {
            RTC.LifeCycleState._CREATED_STATE -> CREATED
            RTC.LifeCycleState._INACTIVE_STATE -> INACTIVE
            RTC.LifeCycleState._ACTIVE_STATE -> ACTIVE
            RTC.LifeCycleState._ERROR_STATE -> ERROR
            else -> UNKNOWN
        }
    }
}
