package org.rtcoord.cli

import java.time.Instant
import java.time.ZoneId
import java.time.format.DateTimeFormatter
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
import org.rtcoord.RootNode
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged

/** The event as `watch` prints it: when the tree noticed it (local time), the source's path, what happened. */
internal fun RtcEvent.line(zone: ZoneId = ZoneId.systemDefault()): String =
    "${timestamp(noticedAt, zone)} $path ${what()}"

/** [millis] since the epoch as `watch` prints times, in local time. */
internal fun timestamp(millis: Long, zone: ZoneId = ZoneId.systemDefault()): String =
    TIMESTAMP.format(Instant.ofEpochMilli(millis).atZone(zone))

/** What happened, in a few words. */
internal fun RtcEvent.what(): String =
    when (this) {
        is StateChanged -> "state in context $handle: $old -> $new"
        is ComponentFinalized -> "finalized"
        is FsmStateChanged -> "FSM state: ${old ?: "(not told)"} -> $new"
        is PortConnected -> "port $port connected (connector ${connector.name}, id ${connector.id})"
        is PortDisconnected -> "port $port disconnected (connector ${connector.name}, id ${connector.id})"
        is PortTraffic -> "port $port ${if (outgoing) "sent" else "received"} data"
        is ParameterChanged -> "parameter $name in set $set: ${old ?: "(none)"} -> ${new ?: "(none)"}"
        is ConfigurationSetActivated -> "active configuration set: ${old ?: "(none)"} -> ${new ?: "(none)"}"
        is ConfigurationSetAdded -> "configuration set $id added"
        is ConfigurationSetRemoved -> "configuration set $id removed"
        is ContextRateChanged -> "rate of context $handle: $old -> $new Hz"
        is ContextRunningChanged -> "context $handle ${if (running) "started" else "stopped"}"
        is ContextAttachmentChanged -> "${if (attached) "joined" else "left"} context $handle"
        is ManagerComponentChanged -> "component $instanceName ${if (created) "created" else "deleted"}"
        is NodeAppeared -> "${child.name} appeared" + (snapshot?.let { ": ${it.brief()}" } ?: "")
        is NodeVanished -> "${child.name} vanished"
        is HeartbeatLost -> "no heartbeat for $silentMillis ms"
        is BecameZombie -> "unreachable: ${cause.reason}"
        is Recovered -> "answers again"
        is WatchMethodChanged -> "${if (old == null) "watched" else "now watched"}: ${new.text()}"
        is ManagerDied ->
            "manager stopped answering (${cause.reason}); " +
                (if (components.isEmpty()) "it hosted no component"
                else "its components went with it: ${components.joinToString { it.name }}")
        is ManagerReturned -> "manager answers again"
        is NameServerLost ->
            "name server unreachable (${cause.reason}); what is registered on it is unknown until it answers"
        is NameServerReturned -> "name server answers again, after ${downMillis / 1000.0} s"
        is LogRecord -> "logged $level ${logger.ifEmpty { "-" }}: $message" + origin()
    }

/** Where a record whose sender the tree has not listed came from: its host, process and manager. */
private fun LogRecord.origin(): String =
    if (source !is RootNode) ""
    else listOfNotNull(host, pid?.let { "pid $it" }, manager?.let { "manager $it" }).joinToString(", ", " (from ", ")")

/** A component as a line shows it: its state, and its ports that have connections. */
internal fun ComponentSnapshot.brief(state: LifeCycle = this.state): String {
    val connected = ports.filter { it.connectors.isNotEmpty() }.joinToString { "${it.name} (${it.connectors.size})" }
    return state.name + if (connected.isEmpty()) ", no connection" else ", connected: $connected"
}

/** How a component is watched, in a few words. */
internal fun WatchMethod.text(): String =
    when (this) {
        is WatchMethod.Pushed ->
            "pushed by its ${flavour.label}, heartbeat every $heartbeat" +
                (pollPeriod?.let { ", and polled every $it" } ?: "")
        is WatchMethod.Polled -> "polled every $period, as $reason"
        is WatchMethod.Unwatched -> "not at all, as $reason"
    }

internal val TIMESTAMP: DateTimeFormatter = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS")
