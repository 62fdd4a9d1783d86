package org.rtcoord.dsl

import kotlin.time.Duration
import org.rtcoord.PortData

/**
 * A rule on the data of an out-port, which the coordinator taps (see [org.rtcoord.Port.tap]): its samples of one type,
 * its silence while the component is ACTIVE, or its rate falling below a floor.
 */
internal sealed class DataRule(val port: PortRef) {
    abstract val description: String

    /**
     * Every sample of [type] ([org.rtcoord.UnknownData] for any type not decoded); the newest waits while the handler
     * runs.
     */
    class Samples<T : PortData>(port: PortRef, val type: Class<T>, val handler: suspend Reaction.(T) -> Unit) :
        DataRule(port) {
        override val description: String
            get() = "data ${type.simpleName} of $port"
    }

    /** No sample for [limit] while the port's component is ACTIVE; fires once per silence. */
    class Silence(port: PortRef, val limit: Duration, val handler: suspend Reaction.() -> Unit) : DataRule(port) {
        override val description: String
            get() = "$port silent for $limit"
    }

    /** Fewer than [rate] samples a second, over the last second, while the component is ACTIVE; fires once per drop. */
    class RateBelow(port: PortRef, val rate: Double, val handler: suspend Reaction.(Double) -> Unit) : DataRule(port) {
        override val description: String
            get() = "$port rate below $rate Hz"
    }
}
