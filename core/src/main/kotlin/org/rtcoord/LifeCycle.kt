package org.rtcoord

/** A component's lifecycle state in one execution context. */
public enum class LifeCycle {
    CREATED,
    INACTIVE,
    ACTIVE,
    ERROR,

    /** The state could not be read. */
    UNKNOWN,
}
