package org.rtcoord.profile.internal

import org.rtcoord.LifeCycle
import org.rtcoord.RtcTree
import org.rtcoord.profile.ExecutionContext
import org.rtcoord.profile.ProfileDifference
import org.rtcoord.profile.RtsProfile

/** Compares the live system with a profile, as rtcheck does, and reports every difference. */
internal class SystemCheck(private val tree: RtcTree) {
    suspend fun check(profile: RtsProfile, state: LifeCycle?): List<ProfileDifference> {
        val system = ResolvedSystem.of(tree, profile)
        val differences =
            system.missing
                .map {
                    ProfileDifference(
                        "/" + it.pathUri.removePrefix("/"),
                        if (it.isRequired) "a running component" else "a running (optional) component",
                        "none",
                    )
                }
                .toMutableList()
        for (c in profile.components) {
            val node = system.nodes[c.instanceName] ?: continue
            val snapshot = node.snapshot()
            val subject = node.path.toString()
            if (state != null) {
                for (ec in c.executionContexts.ifEmpty { listOf(ExecutionContext("0")) }) {
                    val actual = ec.id.toIntOrNull()?.let { snapshot.context(it)?.state } ?: LifeCycle.UNKNOWN
                    if (actual != state)
                        differences += ProfileDifference("$subject context ${ec.id}", state.name, actual.name)
                }
            }
            for (ec in c.executionContexts) {
                val rate = ec.rate ?: continue
                val live = ec.id.toIntOrNull()?.let { snapshot.context(it) } ?: continue
                if (live.rate != rate)
                    differences += ProfileDifference("$subject context ${ec.id}", "rate $rate", "rate ${live.rate}")
            }
            val configuration = node.configuration()
            if (c.activeConfigurationSet.isNotEmpty() && configuration.activeSet != c.activeConfigurationSet) {
                differences +=
                    ProfileDifference(
                        subject,
                        "active configuration set '${c.activeConfigurationSet}'",
                        configuration.activeSet?.let { "'$it'" } ?: "none active",
                    )
            }
            for (set in ConfigurationRestore.restorable(c)) {
                val live = configuration.sets[set.id]
                if (live == null) {
                    differences += ProfileDifference(subject, "configuration set '${set.id}'", "none")
                    continue
                }
                set.data
                    .filter { (k, v) -> live[k] != v }
                    .forEach { (k, v) ->
                        differences +=
                            ProfileDifference(
                                "$subject ${set.id}.$k",
                                "'$v'",
                                live[k]?.let { "'$it'" } ?: "no such parameter",
                            )
                    }
            }
        }
        for (connector in profile.dataPortConnectors + profile.servicePortConnectors) {
            val from = system.node(connector.source) ?: continue
            val to = system.node(connector.target) ?: continue
            val fromPort = connector.source.shortPortName ?: continue
            val toName = "${to.snapshot().instanceName}.${connector.target.shortPortName}"
            val subject = "${from.path}:$fromPort -> ${to.path}:${connector.target.shortPortName}"
            if (from.snapshot().port(fromPort) == null) {
                differences += ProfileDifference("${from.path}:$fromPort", "a port", "none")
                continue
            }
            val connection =
                from.port(fromPort).connections().firstOrNull { c -> c.ports.any { it.fullName == toName } }
            if (connection == null) {
                differences += ProfileDifference(subject, "a connection", "none")
                continue
            }
            connector
                .connectionProperties()
                .filter { (k, v) ->
                    k.startsWith("dataport.") && connection.properties[k] != null && connection.properties[k] != v
                }
                .forEach { (k, v) ->
                    differences += ProfileDifference(subject, "$k=$v", "$k=${connection.properties[k]}")
                }
        }
        return differences
    }
}
