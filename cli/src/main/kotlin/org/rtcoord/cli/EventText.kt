package org.rtcoord.cli

import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ConfigurationSetAdded
import org.rtcoord.ConfigurationSetRemoved
import org.rtcoord.ContextAttachmentChanged
import org.rtcoord.ContextRateChanged
import org.rtcoord.ContextRunningChanged
import org.rtcoord.HeartbeatLost
import org.rtcoord.ManagerComponentChanged
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import java.time.Instant
import java.time.ZoneId
import java.time.format.DateTimeFormatter

/** The event as `watch` prints it: when the tree noticed it (local time), the source's path, what happened. */
internal fun RtcEvent.line(zone: ZoneId = ZoneId.systemDefault()): String =
    "${TIMESTAMP.format(Instant.ofEpochMilli(noticedAt).atZone(zone))} $path ${what()}"

/** The event for `rtcoord --json watch`: time, path, type and the event's own fields. */
internal fun RtcEvent.toJson(): Map<String, Any?> = mapOf(
    "time" to Instant.ofEpochMilli(noticedAt).toString(),
    "path" to path.toString(),
    "event" to javaClass.simpleName,
) + fields()

/** What happened, in a few words. */
internal fun RtcEvent.what(): String = when (this) {
    is StateChanged -> "state in context $handle: $old -> $new"
    is ComponentFinalized -> "finalized"
    is PortConnected -> "port $port connected (connector ${connector.name}, id ${connector.id})"
    is PortDisconnected -> "port $port disconnected (connector ${connector.name}, id ${connector.id})"
    is ParameterChanged -> "parameter $name in set $set: ${old ?: "(none)"} -> ${new ?: "(none)"}"
    is ConfigurationSetActivated -> "active configuration set: $old -> $new"
    is ConfigurationSetAdded -> "configuration set $id added"
    is ConfigurationSetRemoved -> "configuration set $id removed"
    is ContextRateChanged -> "rate of context $handle: $old -> $new Hz"
    is ContextRunningChanged -> "context $handle ${if (running) "started" else "stopped"}"
    is ContextAttachmentChanged -> "${if (attached) "joined" else "left"} context $handle"
    is ManagerComponentChanged -> "component $instanceName ${if (created) "created" else "deleted"}"
    is NodeAppeared -> "${child.name} appeared"
    is NodeVanished -> "${child.name} vanished"
    is HeartbeatLost -> "no heartbeat for $silentMillis ms"
    is BecameZombie -> "unreachable: ${cause.reason}"
    is Recovered -> "answers again"
}

/** The event's own fields for JSON. */
private fun RtcEvent.fields(): Map<String, Any?> = when (this) {
    is StateChanged -> mapOf("handle" to handle, "old" to old.name, "new" to new.name)
    is ComponentFinalized -> emptyMap()
    is PortConnected -> mapOf("port" to port, "connector" to connector.id, "connectorName" to connector.name)
    is PortDisconnected -> mapOf("port" to port, "connector" to connector.id, "connectorName" to connector.name)
    is ParameterChanged -> mapOf("set" to set, "name" to name, "old" to old, "new" to new)
    is ConfigurationSetActivated -> mapOf("old" to old, "new" to new)
    is ConfigurationSetAdded -> mapOf("set" to id)
    is ConfigurationSetRemoved -> mapOf("set" to id)
    is ContextRateChanged -> mapOf("handle" to handle, "old" to old, "new" to new)
    is ContextRunningChanged -> mapOf("handle" to handle, "running" to running)
    is ContextAttachmentChanged -> mapOf("handle" to handle, "attached" to attached)
    is ManagerComponentChanged -> mapOf("instanceName" to instanceName, "created" to created)
    is NodeAppeared -> mapOf("child" to child.path.toString())
    is NodeVanished -> mapOf("child" to child.toString())
    is HeartbeatLost -> mapOf("silentMillis" to silentMillis)
    is BecameZombie -> mapOf("error" to cause.message)
    is Recovered -> emptyMap()
}

private val TIMESTAMP: DateTimeFormatter = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS")
