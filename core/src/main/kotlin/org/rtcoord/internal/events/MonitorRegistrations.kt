package org.rtcoord.internal.events

import org.rtcoord.RtcEvent
import org.rtcoord.WatchMode
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours

/** The registrations one [ComponentMonitor] serves, and what they ask of it together. */
internal class MonitorRegistrations : Iterable<MonitorRegistration> {
    private val all = CopyOnWriteArrayList<MonitorRegistration>()

    override fun iterator(): Iterator<MonitorRegistration> = all.iterator()

    operator fun plusAssign(registration: MonitorRegistration) {
        all += registration
    }

    operator fun minusAssign(registration: MonitorRegistration) {
        all -= registration
    }

    fun isEmpty(): Boolean = all.isEmpty()

    /** Gives [event] to every registration's sink. */
    fun offer(event: RtcEvent) {
        all.forEach { it.sink.offer(event) }
    }

    /** Gives [event], a port's traffic, to the sinks of the registrations that asked for traffic. */
    fun offerTraffic(event: RtcEvent) {
        all.forEach { if (it.traffic) it.sink.offer(event) }
    }

    /** Whether there are some and every one wants states alone. */
    val statesOnly: Boolean get() = all.isNotEmpty() && all.all { it.statesOnly }

    /** Whether any wants the configuration read with the component. */
    val configuration: Boolean get() = all.any { it.configuration }

    /** The push registration with the shortest heartbeat, which the observer serves; null when none pushes. */
    val push: MonitorRegistration? get() = all.filter { it.options.mode != WatchMode.POLL }.minByOrNull { it.options.heartbeat }

    /** The shortest traffic interval a push registration that wants traffic asks for; an hour (next to none) when none does. */
    fun trafficInterval(): Duration =
        all.filter { it.traffic && it.options.mode != WatchMode.POLL }.minOfOrNull { it.options.trafficInterval } ?: NO_TRAFFIC

    private companion object {
        /** The traffic interval asked for when nobody wants traffic: OpenRTM sends data hints every second by default. */
        val NO_TRAFFIC = 1.hours
    }
}
