package org.rtcoord.profile.internal

import org.rtcoord.RtcTree
import org.rtcoord.profile.RtsProfile

/** Removes a profile's connections, as rtteardown does, whatever their connector ids now are. */
internal class SystemTeardown(private val tree: RtcTree) {
    suspend fun teardown(profile: RtsProfile): List<String> {
        val system = ResolvedSystem.of(tree, profile)
        val done = mutableListOf<String>()
        for (connector in profile.dataPortConnectors + profile.servicePortConnectors) {
            val from = system.node(connector.source) ?: continue
            val to = system.node(connector.target) ?: continue
            val port = connector.source.shortPortName?.takeIf { from.snapshot().port(it) != null } ?: continue
            val toName = "${to.snapshot().instanceName}.${connector.target.shortPortName}"
            from
                .port(port)
                .connections()
                .filter { c -> c.ports.any { it.fullName == toName } }
                .forEach { c ->
                    from.port(port).disconnect(c.id)
                    done += "disconnected ${from.path}:$port from ${to.path}:${connector.target.shortPortName}"
                }
        }
        return done
    }
}
