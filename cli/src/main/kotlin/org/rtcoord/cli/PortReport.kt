package org.rtcoord.cli

import org.rtcoord.Connection
import org.rtcoord.Port
import org.rtcoord.PortInterface
import org.rtcoord.PortKind
import org.rtcoord.PortSnapshot
import org.rtcoord.cli.json.ConnectionEndJson
import org.rtcoord.cli.json.ConnectionJson
import org.rtcoord.cli.json.InterfaceJson
import org.rtcoord.cli.json.PortJson

/**
 * What `cat` shows of a port: kind, data type or service interfaces, and its connections with the far ends as tree
 * paths.
 */
internal class PortReport(val snapshot: PortSnapshot, val connections: List<Connection>) {
    /**
     * A heading line `name kind type`, a service port's interfaces (`Provided instance type`), then one line per
     * connection; [long] adds the port's properties below the heading and each connector's below its line.
     */
    fun lines(long: Boolean, indent: String): List<String> = buildList {
        add(indent + listOfNotNull(snapshot.name, kindLabel(snapshot.kind), snapshot.dataType).joinToString("  "))
        if (long) addAll(aligned(sorted(snapshot.properties), "$indent    "))
        addAll(
            aligned(
                snapshot.interfaces.map { listOf(polarityLabel(it.polarity), it.instanceName, it.typeName) },
                "$indent  ",
            )
        )
        val arrow =
            when (snapshot.kind) {
                PortKind.DATA_OUT -> "->"
                PortKind.DATA_IN -> "<-"
                else -> "--"
            }
        connections.forEach { connection ->
            add("$indent  $arrow ${farEnds(connection).joinToString(", ")}")
            if (long) {
                addAll(
                    aligned(
                        listOf(listOf("connector", connection.name), listOf("id", connection.id)) +
                            sorted(connection.properties),
                        "$indent      ",
                    )
                )
            }
        }
    }

    /** The port for `--json`, with its [path] when it is shown alone. */
    fun toJson(path: String? = null): PortJson =
        PortJson(
            snapshot.name,
            kindLabel(snapshot.kind),
            snapshot.dataType,
            snapshot.interfaces.map { InterfaceJson(it.instanceName, it.typeName, it.polarity.name) },
            snapshot.properties.toSortedMap(),
            connections.map { connection ->
                ConnectionJson(
                    connection.id,
                    connection.name,
                    connection.ports.map { ConnectionEndJson(it.fullName, it.path?.toString()) },
                    connection.properties.toSortedMap(),
                )
            },
            path,
        )

    /** The connection's other ports: their tree paths, or OpenRTM's names for ports the tree does not know. */
    private fun farEnds(connection: Connection): List<String> =
        connection.ports
            .filter { it.fullName != snapshot.fullName }
            .map { it.path?.toString() ?: "${it.fullName} (outside the tree)" }

    companion object {
        /** Reads [port] with its connections resolved to paths. */
        suspend fun read(port: Port): PortReport {
            val snapshot = port.snapshot()
            return PortReport(snapshot, if (snapshot.connectors.isEmpty()) emptyList() else port.connections())
        }

        /** A polarity as rtcat prints it: `Provided`, `Required`. */
        fun polarityLabel(polarity: PortInterface.Polarity): String =
            polarity.name.lowercase().replaceFirstChar { it.uppercase() }

        /** The port types OpenRTM writes in `port.port_type`. */
        fun kindLabel(kind: PortKind): String =
            when (kind) {
                PortKind.DATA_IN -> "DataInPort"
                PortKind.DATA_OUT -> "DataOutPort"
                PortKind.SERVICE -> "CorbaPort"
                PortKind.OTHER -> "Port"
            }
    }
}

/** [properties] as key-value rows, by key. */
internal fun sorted(properties: Map<String, String>): List<List<String>> =
    properties.toSortedMap().map { (key, value) -> listOf(key, value) }
