package org.rtcoord.cli.json

import kotlinx.serialization.Serializable
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentSnapshot
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ConfigurationSetAdded
import org.rtcoord.ConfigurationSetRemoved
import org.rtcoord.ContextAttachmentChanged
import org.rtcoord.ContextRateChanged
import org.rtcoord.ContextRunningChanged
import org.rtcoord.FsmStateChanged
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.LogRecord
import org.rtcoord.ManagerComponentChanged
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerReturned
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.PortTraffic
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.WatchMethodChanged

/**
 * An event's own fields, beside its time and path in [EventJson]; each class is named as the event (`event` in the
 * JSON). Lifecycle states are [LifeCycle] names; a field that may be unknown is null.
 */
@Serializable
internal sealed class EventDetail {
    @Serializable class StateChanged(val handle: Int, val old: String, val new: String) : EventDetail()

    @Serializable object ComponentFinalized : EventDetail()

    @Serializable class FsmStateChanged(val old: String?, val new: String) : EventDetail()

    @Serializable
    class PortConnected(val port: String, val connector: String, val connectorName: String) : EventDetail()

    @Serializable
    class PortDisconnected(val port: String, val connector: String, val connectorName: String) : EventDetail()

    @Serializable class PortTraffic(val port: String, val outgoing: Boolean) : EventDetail()

    @Serializable
    class ParameterChanged(val set: String, val name: String, val old: String?, val new: String?) : EventDetail()

    @Serializable class ConfigurationSetActivated(val old: String?, val new: String?) : EventDetail()

    @Serializable class ConfigurationSetAdded(val set: String) : EventDetail()

    @Serializable class ConfigurationSetRemoved(val set: String) : EventDetail()

    @Serializable
    class ContextRateChanged(
        val handle: Int,
        @Serializable(with = FiniteDouble::class) val old: Double,
        @Serializable(with = FiniteDouble::class) val new: Double,
    ) : EventDetail()

    @Serializable class ContextRunningChanged(val handle: Int, val running: Boolean) : EventDetail()

    @Serializable class ContextAttachmentChanged(val handle: Int, val attached: Boolean) : EventDetail()

    @Serializable class ManagerComponentChanged(val instanceName: String, val created: Boolean) : EventDetail()

    /** A [child] appeared; a component's [state] and [connections] (connectors by port) when it was read. */
    @Serializable
    class NodeAppeared(val child: String, val state: String? = null, val connections: Map<String, Int>? = null) :
        EventDetail()

    @Serializable class NodeVanished(val child: String) : EventDetail()

    @Serializable class HeartbeatLost(val silentMillis: Long) : EventDetail()

    @Serializable class BecameZombie(val error: String?) : EventDetail()

    @Serializable object Recovered : EventDetail()

    /** How it was watched before ([was], a method's name; null at first); how it is now is spread beside. */
    @Serializable class WatchMethodChanged(val was: String?) : EventDetail()

    /** A manager stopped answering, and the [components] it hosted (their names) went with it. */
    @Serializable class ManagerDied(val components: List<String>, val error: String?) : EventDetail()

    @Serializable object ManagerReturned : EventDetail()

    @Serializable class NameServerLost(val error: String?) : EventDetail()

    @Serializable class NameServerReturned(val downMillis: Long) : EventDetail()

    /**
     * A log record: when its sender stamped it ([loggedAt], ISO-8601 in UTC), its [level], [logger] and [message], and
     * the process that sent it.
     */
    @Serializable
    class LogRecord(
        val loggedAt: String,
        val level: String,
        val logger: String,
        val message: String,
        val pid: Long?,
        val host: String?,
        val manager: String?,
        val tag: String,
    ) : EventDetail()

    /**
     * A component as `watch` finds it when it starts: its [state], its [connections] when it was read, its FSM when it
     * has one, whether it is [alive]; how it is watched is spread beside.
     */
    @Serializable
    class Present(
        val state: String,
        val connections: Map<String, Int>? = null,
        val fsm: FsmJson? = null,
        val alive: Boolean,
    ) : EventDetail()

    /** An out-port's [rate] in samples per second over the last period (`watch --data`). */
    @Serializable class DataRate(@Serializable(with = FiniteDouble::class) val rate: Double) : EventDetail()

    companion object {
        /** [snapshot]'s ports that have connectors, with how many each. */
        fun connections(snapshot: ComponentSnapshot): Map<String, Int> =
            snapshot.ports.filter { it.connectors.isNotEmpty() }.associate { it.name to it.connectors.size }
    }
}

/** [event]'s own fields. */
internal fun eventDetail(event: RtcEvent): EventDetail =
    when (event) {
        is StateChanged -> EventDetail.StateChanged(event.handle, event.old.name, event.new.name)
        is ComponentFinalized -> EventDetail.ComponentFinalized
        is FsmStateChanged -> EventDetail.FsmStateChanged(event.old, event.new)
        is PortConnected -> EventDetail.PortConnected(event.port, event.connector.id, event.connector.name)
        is PortDisconnected -> EventDetail.PortDisconnected(event.port, event.connector.id, event.connector.name)
        is PortTraffic -> EventDetail.PortTraffic(event.port, event.outgoing)
        is ParameterChanged -> EventDetail.ParameterChanged(event.set, event.name, event.old, event.new)
        is ConfigurationSetActivated -> EventDetail.ConfigurationSetActivated(event.old, event.new)
        is ConfigurationSetAdded -> EventDetail.ConfigurationSetAdded(event.id)
        is ConfigurationSetRemoved -> EventDetail.ConfigurationSetRemoved(event.id)
        is ContextRateChanged -> EventDetail.ContextRateChanged(event.handle, event.old, event.new)
        is ContextRunningChanged -> EventDetail.ContextRunningChanged(event.handle, event.running)
        is ContextAttachmentChanged -> EventDetail.ContextAttachmentChanged(event.handle, event.attached)
        is ManagerComponentChanged -> EventDetail.ManagerComponentChanged(event.instanceName, event.created)
        is NodeAppeared ->
            EventDetail.NodeAppeared(
                event.child.path.toString(),
                event.snapshot?.state?.name,
                event.snapshot?.let { EventDetail.connections(it) },
            )
        is NodeVanished -> EventDetail.NodeVanished(event.child.toString())
        is HeartbeatLost -> EventDetail.HeartbeatLost(event.silentMillis)
        is BecameZombie -> EventDetail.BecameZombie(event.cause.message)
        is Recovered -> EventDetail.Recovered
        is WatchMethodChanged -> EventDetail.WatchMethodChanged(event.old?.let { WatchMethodJson.of(it).method })
        is ManagerDied -> EventDetail.ManagerDied(event.components.map { it.name }, event.cause.message)
        is ManagerReturned -> EventDetail.ManagerReturned
        is NameServerLost -> EventDetail.NameServerLost(event.cause.message)
        is NameServerReturned -> EventDetail.NameServerReturned(event.downMillis)
        is LogRecord ->
            EventDetail.LogRecord(
                java.time.Instant.ofEpochMilli(event.loggedAt).toString(),
                event.level.name,
                event.logger,
                event.message,
                event.pid,
                event.host,
                event.manager,
                event.tag,
            )
    }
