package org.rtcoord.cli

import org.rtcoord.ConnectorSnapshot
import org.rtcoord.Port

/**
 * The connectors joining this port and [other]: those both hold, by connector id (OpenRTM gives every connector a UUID,
 * and each port of a connection records it under that id).
 */
internal suspend fun Port.connectorsTo(other: Port): List<ConnectorSnapshot> {
    val theirs = other.snapshot().connectors.map { it.id }.toSet()
    return snapshot().connectors.filter { it.id in theirs }
}
