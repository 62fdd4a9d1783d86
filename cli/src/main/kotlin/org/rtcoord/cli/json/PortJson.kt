package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/**
 * A port as `cat --json` gives it, alone (with its [path]) or in its component's report: its kind (OpenRTM's
 * `port.port_type`), data type, service interfaces, properties and connections.
 */
@Serializable
internal class PortJson(
    val name: String,
    /** `DataInPort`, `DataOutPort`, `CorbaPort` or `Port`. */
    val kind: String,
    val dataType: String?,
    val interfaces: List<InterfaceJson>,
    val properties: Map<String, String>,
    val connections: List<ConnectionJson>,
    /** The port's path, when `cat` was given a port. */
    val path: String? = null,
)

/** A service port's interface; [polarity] is `PROVIDED` or `REQUIRED`. */
@Serializable internal class InterfaceJson(val instanceName: String, val typeName: String, val polarity: String)

/** A port's connection: its connector's [id] and [name], the [ports] it joins and its [properties]. */
@Serializable
internal class ConnectionJson(
    val id: String,
    val name: String,
    val ports: List<ConnectionEndJson>,
    val properties: Map<String, String>,
)

/** A connected port: OpenRTM's full [name], and its [path] in the tree (null when the tree does not know it). */
@Serializable internal class ConnectionEndJson(val name: String, val path: String?)
