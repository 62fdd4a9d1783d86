package org.rtcoord.internal.events

import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ConfigurationSetAdded
import org.rtcoord.ConfigurationSetRemoved
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.ContextAttachmentChanged
import org.rtcoord.ContextRateChanged
import org.rtcoord.ContextRunningChanged
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.RtcEvent

/**
 * The events between two snapshots of one component, lifecycle states excepted (a [StateTracker] reconciles those with
 * the hints): contexts joined or left, rates and running changed, connections made or removed, configuration sets and
 * parameters changed.
 */
internal fun differences(source: ComponentNode, old: ComponentSnapshot, new: ComponentSnapshot): List<RtcEvent> =
    buildList {
        val before = old.contexts.associateBy { it.handle }
        val after = new.contexts.associateBy { it.handle }
        (after.keys - before.keys).sorted().forEach { add(ContextAttachmentChanged(source, it, attached = true)) }
        (before.keys - after.keys).sorted().forEach { add(ContextAttachmentChanged(source, it, attached = false)) }
        for ((handle, now) in after) {
            val was = before[handle] ?: continue
            if (was.rate != now.rate) add(ContextRateChanged(source, handle, was.rate, now.rate))
            if (was.running != now.running) add(ContextRunningChanged(source, handle, now.running))
        }

        val oldPorts = old.ports.associateBy { it.name }
        for (port in new.ports) {
            val was = oldPorts[port.name]?.connectors?.associateBy { it.id }.orEmpty()
            val now = port.connectors.associateBy { it.id }
            (now.keys - was.keys).forEach { add(PortConnected(source, port.name, now.getValue(it))) }
            (was.keys - now.keys).forEach { add(PortDisconnected(source, port.name, was.getValue(it))) }
        }
        val vanishedPorts = oldPorts.keys - new.ports.map { it.name }.toSet()
        vanishedPorts.forEach { name ->
            oldPorts.getValue(name).connectors.forEach { add(PortDisconnected(source, name, it)) }
        }

        val was = old.configuration
        val now = new.configuration
        if (was != null && now != null) addAll(configurationDifferences(source, was, now))
    }

private fun configurationDifferences(
    source: ComponentNode,
    old: ConfigurationSnapshot,
    new: ConfigurationSnapshot,
): List<RtcEvent> = buildList {
    (new.sets.keys - old.sets.keys).forEach { add(ConfigurationSetAdded(source, it)) }
    (old.sets.keys - new.sets.keys).forEach { add(ConfigurationSetRemoved(source, it)) }
    for ((set, values) in new.sets) {
        val before = old.sets[set] ?: continue
        for (name in (before.keys + values.keys)) {
            if (before[name] != values[name]) add(ParameterChanged(source, set, name, before[name], values[name]))
        }
    }
    if (old.activeSet != new.activeSet) add(ConfigurationSetActivated(source, old.activeSet, new.activeSet))
}
