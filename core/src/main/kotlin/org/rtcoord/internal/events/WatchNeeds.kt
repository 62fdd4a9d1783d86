package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import org.rtcoord.EventOptions
import org.rtcoord.WatchMode

/**
 * What the registrations of one component ask of its watching together, as its monitor found them at the start of a
 * batch: their [options], whether every one wants states alone ([statesOnly]: then a tick reads states only), the
 * traffic interval its observer is asked for ([traffic]), and the shortest heartbeat the tree takes now
 * ([heartbeatFloor], see [HeartbeatBudget]).
 */
internal class WatchNeeds(
    val options: List<EventOptions>,
    val statesOnly: Boolean,
    val traffic: Duration,
    heartbeatFloor: Duration = Duration.ZERO,
) {
    /**
     * The options of the push registration with the shortest heartbeat, which the observer serves; null when none
     * pushes.
     */
    val push: EventOptions? = options.filter { it.mode != WatchMode.POLL }.minByOrNull { it.heartbeat }

    /** The heartbeat the observer is asked for: [push]'s, or the floor when that is longer; null when none pushes. */
    val heartbeat: Duration? = push?.heartbeat?.coerceAtLeast(heartbeatFloor)

    companion object {
        /**
         * The traffic interval asked for when nobody wants traffic: OpenRTM sends data hints every second by default.
         */
        val NO_TRAFFIC: Duration = 1.hours

        /** No registration: nothing is watched. */
        val NONE: WatchNeeds = WatchNeeds(emptyList(), statesOnly = false, traffic = NO_TRAFFIC)
    }
}
