package org.rtcoord

import RTC.PortService
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.channels.awaitClose
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.buffer
import kotlinx.coroutines.flow.callbackFlow
import kotlinx.coroutines.launch
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.PortCalls
import org.rtcoord.internal.ValueFields

/**
 * A port of a component, addressed as `component.rtc:name`: [ComponentNode.port] gives it. The class is sealed for the
 * reason [Node] gives.
 */
public sealed class Port(
    /** The component the port belongs to. */
    public val component: ComponentNode,
    /** The port's name without the instance prefix. */
    public val name: String,
) {
    /** `/host:port/ctx/component.rtc:name`. */
    public val path: RtcPath
        get() = component.path.withPort(name)

    private val subject: String
        get() = path.toString()

    /** Where its remote calls are made. */
    private val calls: PortCalls
        get() = PortCalls(component.core, subject, component.component, component.path.toString(), name)

    /** The port as last read. */
    @JvmSynthetic
    public suspend fun snapshot(): PortSnapshot =
        component.snapshot().port(name) ?: throw NotFoundException(subject, "the port is gone")

    /**
     * Connects this port to [others] and returns the new connector. [properties] override OpenRTM's usual data port
     * defaults (push, corba_cdr, flush, this port's data type). Incompatible ports or properties are refused before
     * anything changes.
     */
    @JvmSynthetic
    public suspend fun connect(
        others: List<Port>,
        properties: Map<String, String> = emptyMap(),
        name: String? = null,
        id: String = "",
    ): ConnectorSnapshot {
        val merged = connectable(others, properties)
        val ports = listOf(this) + others
        val connectorName =
            name ?: ports.joinToString("_") { "${it.component.name.substringBeforeLast('.')}.${it.name}" }
        val made =
            calls.connect(
                others.map { it.calls },
                merged,
                connectorName,
                id,
                others.joinToString { it.path.toString() },
            )
        refreshAll(ports)
        return made
    }

    /**
     * The properties a connection of this port to [others] would get (OpenRTM's defaults overridden by [properties]);
     * fails as [connect] would if the ports or properties do not fit. Changes nothing.
     */
    @JvmSynthetic
    internal suspend fun connectable(others: List<Port>, properties: Map<String, String>): Map<String, String> {
        require(others.isNotEmpty()) { "connect needs at least one other port" }
        val ports = listOf(this) + others
        val snapshots = ports.map { it.snapshot() }
        val merged = defaults(snapshots.first()) + properties
        checkCompatible(ports, snapshots, merged)
        return merged
    }

    /** Removes the connection [connectorId] from this port and its peers. */
    @JvmSynthetic
    public suspend fun disconnect(connectorId: String) {
        refreshAfter(calls.disconnect(connectorId))
    }

    /**
     * Removes every connection of this port, then reads each component involved once. A connection that went meanwhile
     * (its peer or the component dropped it since the port was read: OpenRTM-aist answers `BAD_PARAMETER` for an id it
     * no longer has) is passed over: it is gone, as this asks.
     */
    @JvmSynthetic
    public suspend fun disconnectAll() {
        refreshAfter(
            snapshot().connectors.flatMap { connector ->
                try {
                    calls.disconnect(connector.id)
                } catch (e: BadParameterException) {
                    if (connector.id in calls.connectorIds()) throw e
                    emptyList()
                }
            }
        )
    }

    /** This port's connections, each with its ports resolved to tree paths where the tree knows them. */
    @JvmSynthetic public suspend fun connections(): List<Connection> = calls.connections()

    /** Reads this component and [peers] again, each once. */
    private suspend fun refreshAfter(peers: List<ComponentObject>) = coroutineScope {
        (peers + component.component).distinct().forEach { peer -> launch { runCatching { peer.refresh(subject) } } }
    }

    /**
     * Subscribes [listener] to this out-port's data and returns once it is subscribed. The tree taps the port as a
     * connected in-port would (see [PortData] for what arrives): one tap per port, shared by every listener, whose
     * connector (id and name starting `rtcoord-tap-`) shows in the port's connections while any listener is subscribed.
     * Cancelling the last listener removes the tap, and so does closing the tree; a tree that died leaves its tap
     * behind, and the next tree tapping the port removes it. Fails for a port that is not a data out-port, or that
     * refuses the connection.
     */
    @JvmSynthetic
    public suspend fun tap(listener: DataListener): Subscription = component.core.taps.subscribe(this, listener)

    /**
     * This out-port's samples while the flow is collected (see [tap]). A collector slower than the port loses the
     * oldest samples beyond the [capacity] waiting for it, never the newest.
     */
    @JvmSynthetic
    public fun data(capacity: Int = 64): Flow<PortData> = callbackFlow {
        val subscription = tap { trySend(it) }
        awaitClose { subscription.cancel() }
    }
        .buffer(capacity, BufferOverflow.DROP_OLDEST)

    /** The port's object reference, as its component's last read found it. */
    @JvmSynthetic internal suspend fun reference(): PortService = calls.reference()

    private fun defaults(first: PortSnapshot): Map<String, String> = buildMap {
        if (first.kind == PortKind.DATA_IN || first.kind == PortKind.DATA_OUT) {
            put("dataport.dataflow_type", "push")
            put("dataport.interface_type", "corba_cdr")
            put("dataport.subscription_type", "flush")
            first.dataType?.let { put("dataport.data_type", it) }
        }
    }

    private fun checkCompatible(ports: List<Port>, snapshots: List<PortSnapshot>, properties: Map<String, String>) {
        ports
            .withIndex()
            .firstOrNull { (index, port) ->
                ports.take(index).any { it.name == port.name && it.component.isSameComponent(port.component) }
            }
            ?.let { (_, port) ->
                throw BadParameterException(
                    subject,
                    "connect",
                    "${port.path} is given twice: a port cannot connect to itself",
                )
            }
        val data = snapshots.map { it.kind == PortKind.DATA_IN || it.kind == PortKind.DATA_OUT }
        if (data.distinct().size > 1)
            throw BadParameterException(subject, "connect", "cannot connect a data port to a service port")
        if (!data.first()) return
        // A port of type "any" takes every type: OpenRTM-aist's EventInPort, an FSM's event port, is one.
        val types = snapshots.mapNotNull { it.dataType }.filterNot { it.equals("any", ignoreCase = true) }.distinct()
        if (types.size > 1) {
            throw BadParameterException(
                subject,
                "connect",
                "incompatible data types: " +
                    ports.zip(snapshots).joinToString { (port, s) -> "${port.path} carries ${s.dataType}" },
            )
        }
        if (snapshots.none { it.kind == PortKind.DATA_OUT } || snapshots.none { it.kind == PortKind.DATA_IN }) {
            throw BadParameterException(subject, "connect", "a data connection needs an out-port and an in-port")
        }
        for (key in listOf("dataport.dataflow_type", "dataport.interface_type", "dataport.subscription_type")) {
            val wanted = properties[key] ?: continue
            ports.zip(snapshots).forEach { (port, s) ->
                val offered = s.properties[key]?.split(',')?.map { it.trim() } ?: return@forEach
                if (wanted !in offered && offered.none { it.equals("any", ignoreCase = true) }) {
                    throw BadParameterException(
                        subject,
                        "connect",
                        "${port.path} does not offer $key=$wanted (offers ${offered.joinToString(",")})",
                    )
                }
            }
        }
    }

    private suspend fun refreshAll(ports: List<Port>) = coroutineScope {
        ports.map { it.component }.distinctBy { it.component }.map { async { it.refresh() } }.awaitAll()
    }

    override fun toString(): String = "port $path"
}

/** The [Port]s a component gives. */
internal class PortImpl(component: ComponentNode, name: String) : Port(component, name)

/** A connection as read from one of its ports. */
public class Connection(
    public val id: String,
    public val name: String,
    public val properties: Map<String, String>,
    public val ports: List<End>,
) : ValueObject() {
    /** One connected port: OpenRTM's name for it and, where the tree knows its component, its path. */
    public class End(public val fullName: String, public val path: RtcPath?) : ValueObject() {
        override fun fields(): ValueFields = ValueFields("fullName" to fullName, "path" to path)
    }

    override fun fields(): ValueFields =
        ValueFields("id" to id, "name" to name, "properties" to properties, "ports" to ports)
}
