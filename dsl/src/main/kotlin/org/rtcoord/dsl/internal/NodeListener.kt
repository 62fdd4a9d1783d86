package org.rtcoord.dsl.internal

import org.rtcoord.Node
import org.rtcoord.RtcEvent

/** What takes one node's events for a rule or a machine: it reads the node first, then takes its events in order. */
internal interface NodeListener {
    /** Reads [node] before its first event, and again when a component the script names is re-created. */
    suspend fun prepare(node: Node)

    suspend fun deliver(event: RtcEvent)
}
