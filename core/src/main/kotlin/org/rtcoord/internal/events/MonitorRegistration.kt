package org.rtcoord.internal.events

import org.rtcoord.EventOptions

/**
 * One registration's needs of a [ComponentMonitor]: [configuration] when it wants configuration events, [statesOnly]
 * when it wants nothing but lifecycle and liveness events (then a poll tick reads only the states), [traffic] when it
 * asked for [org.rtcoord.PortTraffic] by name (data hints are many: nobody gets them without asking).
 */
internal class MonitorRegistration(
    val sink: EventSink,
    val options: EventOptions,
    val configuration: Boolean,
    val statesOnly: Boolean,
    val traffic: Boolean = false,
) {
    /**
     * Whether it was told how the component is watched: then it knows the monitor's [ComponentMonitor.method]. Owned by
     * the monitor's coroutine.
     */
    var told: Boolean = false
}
