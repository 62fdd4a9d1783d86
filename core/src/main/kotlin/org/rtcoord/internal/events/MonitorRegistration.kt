package org.rtcoord.internal.events

import org.rtcoord.EventOptions
import org.rtcoord.WatchMethod

/**
 * One registration's needs of a [ComponentMonitor]: [configuration] when it wants configuration events,
 * [statesOnly] when it wants nothing but lifecycle and liveness events (then a poll tick reads only the
 * states), [traffic] when it asked for [org.rtcoord.PortTraffic] by name (data hints are many: nobody gets
 * them without asking).
 */
internal class MonitorRegistration(
    val sink: EventSink,
    val options: EventOptions,
    val configuration: Boolean,
    val statesOnly: Boolean,
    val traffic: Boolean = false,
) {
    /** How the component is watched, as this registration was last told; owned by the monitor's coroutine. */
    var told: WatchMethod? = null
}
