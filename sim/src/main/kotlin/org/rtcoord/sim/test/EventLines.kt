package org.rtcoord.sim.test

import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ContextRateChanged
import org.rtcoord.ContextRunningChanged
import org.rtcoord.FsmStateChanged
import org.rtcoord.HeartbeatLost
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
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged

/** A system event as a scenario's timeline shows it, in one line: `laser0.rtc ACTIVE -> ERROR`. */
internal object EventLines {
    fun of(event: RtcEvent): String {
        val name = event.source.name
        return when (event) {
            is StateChanged ->
                "$name ${event.old} -> ${event.new}" + if (event.handle != 0) " (context ${event.handle})" else ""
            is FsmStateChanged -> "$name FSM ${event.old ?: "?"} -> ${event.new}"
            is PortConnected -> "$name:${event.port} connected (${event.connector.name})"
            is PortDisconnected -> "$name:${event.port} disconnected (${event.connector.name})"
            is ParameterChanged -> "$name parameter ${event.set}.${event.name}: ${event.old} -> ${event.new}"
            is ConfigurationSetActivated -> "$name configuration set ${event.old} -> ${event.new}"
            is ContextRateChanged -> "$name context ${event.handle} rate ${event.old} -> ${event.new} Hz"
            is ContextRunningChanged -> "$name context ${event.handle} ${if (event.running) "started" else "stopped"}"
            is ManagerComponentChanged -> "$name ${if (event.created) "created" else "deleted"} ${event.instanceName}"
            is NodeAppeared -> "${event.child.path} appeared"
            is NodeVanished -> "${event.child} vanished"
            is HeartbeatLost -> "$name lost: silent for ${event.silentMillis} ms"
            is BecameZombie -> "$name unreachable: ${event.cause.reason}"
            is Recovered -> "$name recovered"
            is ComponentFinalized -> "$name exited"
            is ManagerDied ->
                "manager $name died, with ${event.components.joinToString { it.name }.ifEmpty { "no components" }}"
            is ManagerReturned -> "manager $name answers again"
            is NameServerLost -> "name server ${event.path} lost: ${event.cause.reason}"
            is NameServerReturned -> "name server ${event.path} back after ${event.downMillis} ms"
            else -> "$name ${event.javaClass.simpleName}"
        }
    }
}
