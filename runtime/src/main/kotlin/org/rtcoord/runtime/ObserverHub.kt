package org.rtcoord.runtime

import _SDOPackage.InvalidParameter
import _SDOPackage.NameValue
import _SDOPackage.ServiceProfile
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import org.slf4j.LoggerFactory

/**
 * The observers attached to one component through `add_service_profile`, and the hints it sends them. As in
 * OpenRTM-aist, a hint is sent by the thread that raised it, before the raising call returns: the hints of one
 * transition leave in order, ahead of anything the component does next (an abort's INACTIVE and ERROR leave before a
 * reset that follows can begin). The calls are oneway, so an observer that is slow to handle them holds nobody up; one
 * whose call fails is dropped, as OpenRTM does. Heartbeats come from a timer of their own.
 */
internal class ObserverHub(
    private val owner: String,
    private val accepted: Set<ObserverFlavour>,
    private val scope: CoroutineScope,
    /** How long a robot's time lasts on this host's clock (see [RuntimeProcess.speed]). */
    private val onHost: (Duration) -> Duration,
    private val paused: () -> Boolean,
) {
    private class Subscription(
        val profile: ServiceProfile,
        val flavour: ObserverFlavour,
        val kinds: Set<StatusKind>,
        val period: Duration?,
        /** `port_profile.send_event.min_interval` and `receive_event.min_interval`, in nanoseconds. */
        val sendInterval: Long,
        val receiveInterval: Long,
    ) {
        /** When each port last told this observer of its traffic (System.nanoTime), per hint. */
        val lastTraffic = ConcurrentHashMap<String, Long>()

        val id: String
            get() = profile.id

        val target: org.omg.CORBA.Object
            get() = profile.service

        @Volatile var heartbeats: Job? = null
    }

    private val log = LoggerFactory.getLogger(ObserverHub::class.java)
    private val subscriptions = ConcurrentHashMap<String, Subscription>()
    private val sentHeartbeats = AtomicLong()

    /** How many heartbeats were sent so far, to every observer together. */
    val heartbeats: Long
        get() = sentHeartbeats.get()

    /** The ids of attached observers. */
    val ids: Set<String>
        get() = subscriptions.keys

    /** The references of attached observers, as the coordinator handed them over. */
    val references: List<org.omg.CORBA.Object>
        get() = subscriptions.values.map { it.target }

    /** The profiles of attached observers, as they were added. */
    val profiles: List<ServiceProfile>
        get() = subscriptions.values.map { it.profile }

    /** Handles `add_service_profile`: false when the flavour is not one this component accepts. */
    fun add(profile: ServiceProfile): Boolean {
        if (profile.id.isNullOrEmpty()) throw InvalidParameter("a service profile needs an id")
        val flavour = ObserverFlavour.values().firstOrNull { it.repositoryId == profile.interface_type }
        if (flavour == null || flavour !in accepted || profile.service == null) return false
        val properties = profile.properties.associate { it.name to it.stringValue() }
        val kinds = observedKinds(properties["observed_status"].orEmpty())
        val subscription =
            Subscription(
                profile,
                flavour,
                kinds,
                heartbeatInterval(flavour, properties)?.let(onHost),
                trafficInterval(properties["port_profile.send_event.min_interval"]),
                trafficInterval(properties["port_profile.receive_event.min_interval"]),
            )
        subscriptions.put(profile.id, subscription)?.heartbeats?.cancel()
        subscription.heartbeats =
            subscription.period?.let { period ->
                scope.launch {
                    while (isActive) {
                        delay(period)
                        if (!paused()) {
                            send(subscription, StatusKind.HEARTBEAT, "")
                            sentHeartbeats.incrementAndGet()
                        }
                    }
                }
            }
        return true
    }

    /** Handles `remove_service_profile`. */
    fun remove(id: String): Boolean {
        val removed = subscriptions.remove(id) ?: throw InvalidParameter("no observer '$id'")
        removed.heartbeats?.cancel()
        return true
    }

    /** Sends [hint] of [kind] to every observer that asked for that kind. */
    fun raise(kind: StatusKind, hint: String) {
        for (subscription in subscriptions.values) if (kind in subscription.kinds) send(subscription, kind, hint)
    }

    /**
     * Sends an FSM action hint (`Idle POST_ONENTRY`) as FSM_STATUS to the observers that asked for FSM_STRUCTURE: C++
     * OpenRTM-aist 2.0 registers its FSM action listeners for that kind
     * (`ComponentObserverConsumer::setFSMStructureListeners`).
     */
    fun raiseFsm(hint: String) {
        for (subscription in subscriptions.values) if (StatusKind.FSM_STRUCTURE in subscription.kinds)
            send(subscription, StatusKind.FSM_STATUS, hint)
    }

    /**
     * Tells the OpenRTM-flavour observers that asked for PORT_PROFILE that a port sent ([outgoing]) or received data:
     * `SEND:OutPort:<port>` or `RECEIVE:InPort:<port>`, to each observer only when more than its interval passed since
     * it was last told of that port's traffic, as the DataPortAction of OpenRTM-aist's ComponentObserverConsumer does.
     */
    fun raiseTraffic(fullPortName: String, outgoing: Boolean) {
        if (subscriptions.isEmpty()) return
        val hint = if (outgoing) "SEND:OutPort:$fullPortName" else "RECEIVE:InPort:$fullPortName"
        val now = System.nanoTime()
        for (subscription in subscriptions.values) {
            if (subscription.flavour != ObserverFlavour.OPENRTM || StatusKind.PORT_PROFILE !in subscription.kinds)
                continue
            val interval = if (outgoing) subscription.sendInterval else subscription.receiveInterval
            val last = subscription.lastTraffic[hint]
            if (last != null && now - last <= interval) continue
            subscription.lastTraffic[hint] = now
            send(subscription, StatusKind.PORT_PROFILE, hint)
        }
    }

    /** Detaches everything; the component is gone. */
    fun close() {
        subscriptions.values.forEach { it.heartbeats?.cancel() }
        subscriptions.clear()
    }

    private fun send(subscription: Subscription, kind: StatusKind, hint: String) {
        try {
            when (subscription.flavour) {
                ObserverFlavour.OPENRTM ->
                    kind.openRtm?.let {
                        OpenRTM.ComponentObserverHelper.unchecked_narrow(subscription.target).update_status(it, hint)
                    }
                ObserverFlavour.OMG ->
                    RTC.ComponentObserverHelper.unchecked_narrow(subscription.target).update_status(kind.omg, hint)
            }
        } catch (e: org.omg.CORBA.SystemException) {
            log.debug("{}: dropping observer {} after {}", owner, subscription.id, e.toString())
            subscriptions.remove(subscription.id, subscription)
            subscription.heartbeats?.cancel()
        }
    }

    private fun observedKinds(value: String): Set<StatusKind> {
        val names = value.split(',').map { it.trim().uppercase() }.filter { it.isNotEmpty() }
        if (names.isEmpty() || "ALL" in names) return StatusKind.values().toSet()
        return StatusKind.values()
            .filter { kind ->
                kind.name in names || (kind == StatusKind.HEARTBEAT && "RTC_HEARTBEAT" in names)
            }
            .toSet()
    }

    /**
     * An interval in seconds of the robot's time as a decimal, one second (OpenRTM's default) when absent or malformed,
     * in nanoseconds of the host's.
     */
    private fun trafficInterval(value: String?): Long =
        onHost((value?.trim()?.toDoubleOrNull()?.takeIf { it >= 0 } ?: 1.0).seconds).inWholeNanoseconds

    private fun heartbeatInterval(flavour: ObserverFlavour, properties: Map<String, String>): Duration? {
        fun key(name: String) =
            if (flavour == ObserverFlavour.OMG) properties["rtc_$name"] ?: properties[name] else properties[name]
        if (key("heartbeat.enable")?.trim()?.uppercase() != "YES") return null
        val seconds = key("heartbeat.interval")?.trim()?.toDoubleOrNull()?.takeIf { it > 0 } ?: 1.0
        return seconds.seconds
    }
}

/** The string an SDO name-value pair carries, whatever else it may hold. */
internal fun NameValue.stringValue(): String = runCatching { value.extract_string() }.getOrElse { value.toString() }
