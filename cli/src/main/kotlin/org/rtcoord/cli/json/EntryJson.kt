package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/** One node as `ls --json` lists it; a component's [state] and [ports] when it was read and answers. */
@Serializable
internal class EntryJson(
    val path: String,
    val name: String,
    /** The node's kind in lower case (`component`, `context`, `manager`...), or `zombie` for a dead registration. */
    val kind: String,
    /** Why a zombie is dead. */
    val error: String? = null,
    /** The component's overall state, a LifeCycle name. */
    val state: String? = null,
    val ports: PortCountsJson? = null,
)

/** A component's ports counted: all of them, in-ports, out-ports and service ports. */
@Serializable
internal class PortCountsJson(
    val all: PortCountJson,
    val `in`: PortCountJson,
    val out: PortCountJson,
    val service: PortCountJson,
)

/** How many ports there are, and how many of them have a connection. */
@Serializable internal class PortCountJson(val total: Int, val connected: Int)
