package org.rtcoord.sim

import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.RtsProfile

/** The connections of both systems, matched by the ports they join and their name. */
internal class ConnectionDifferences(live: RtsProfile, simulated: RtsProfile) {
    private val a = byEnds(live)
    private val b = byEnds(simulated)
    val count: Int
        get() = a.size

    fun differences(): List<String> =
        (a.keys + b.keys).sorted().flatMap { key ->
            val subject = "connection $key"
            val ca = a[key]
            val cb = b[key]
            when {
                ca == null -> listOf("$subject: none live, one simulated")
                cb == null -> listOf("$subject: one live, none simulated")
                else -> {
                    val pa = ca.connectionProperties()
                    val pb = cb.connectionProperties()
                    listOfNotNull(
                        ("$subject: id: ${ca.connectorId} live, ${cb.connectorId} simulated").takeIf {
                            ca.connectorId != cb.connectorId
                        }
                    ) +
                        (pa.keys + pb.keys)
                            .sorted()
                            .filter { pa[it] != pb[it] }
                            .map { "$subject: $it: ${pa[it].shown()} live, ${pb[it].shown()} simulated" }
                }
            }
        }

    private companion object {
        /** `a.out -> b.in (name)` for a data connection; a service connection's ports in name order, joined by `--`. */
        fun byEnds(profile: RtsProfile): Map<String, PortConnector> =
            profile.dataPortConnectors.associateBy { "${it.source.portName} -> ${it.target.portName} (${it.name})" } +
                profile.servicePortConnectors.associateBy { connector ->
                    listOf(connector.source.portName, connector.target.portName)
                        .sortedBy { it.orEmpty() }
                        .joinToString(" -- ") + " (${connector.name})"
                }
    }
}
