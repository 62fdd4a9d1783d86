package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import org.rtcoord.RtcEvent
import org.rtcoord.WatchMode

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

    /** Whether any wants the configuration read with the component. */
    val configuration: Boolean
        get() = all.any { it.configuration }

    /**
     * What they ask of the watching now; the shortest traffic interval a push registration that wants traffic asks for
     * is the observer's, and its heartbeat no shorter than [heartbeatFloor].
     */
    fun needs(heartbeatFloor: Duration = Duration.ZERO): WatchNeeds {
        // A copy of the array as it is: Kotlin's toList reads a one-element list's element after its size, and a
        // registration removed in between made it fail.
        val now = ArrayList(all)
        val traffic =
            now.filter { it.traffic && it.options.mode != WatchMode.POLL }.minOfOrNull { it.options.trafficInterval }
        return WatchNeeds(
            now.map { it.options },
            statesOnly = now.isNotEmpty() && now.all { it.statesOnly },
            traffic = traffic ?: WatchNeeds.NO_TRAFFIC,
            heartbeatFloor,
        )
    }
}
