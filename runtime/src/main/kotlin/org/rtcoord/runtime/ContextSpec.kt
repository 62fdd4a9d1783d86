package org.rtcoord.runtime

import RTC.ExecutionKind

/**
 * An execution context a component owns: the [kind] its profile reports, its [rate] in Hz and the implementation it is
 * an instance of ([typeName], the profile's `type` property). Whatever the kind, it runs its participants at its rate,
 * as OpenRTM-aist-Python's `EventDrivenExecutionContext` (a `PeriodicExecutionContext` that reports `EVENT_DRIVEN`)
 * does.
 */
public class ContextSpec
@JvmOverloads
constructor(
    public val rate: Double,
    public val kind: Kind = Kind.PERIODIC,
    public val typeName: String = kind.defaultTypeName,
) {
    init {
        require(rate > 0.0) { "an execution context needs a positive rate, not $rate" }
    }

    /** `RTC::ExecutionKind`, with the implementation OpenRTM-aist provides for each. */
    public enum class Kind(internal val idl: ExecutionKind, public val defaultTypeName: String) {
        PERIODIC(ExecutionKind.PERIODIC, "PeriodicExecutionContext"),
        EVENT_DRIVEN(ExecutionKind.EVENT_DRIVEN, "EventDrivenExecutionContext"),
        OTHER(ExecutionKind.OTHER, "ExecutionContextBase"),
    }

    override fun toString(): String = "$typeName ($kind, $rate Hz)"
}
