package org.rtcoord.internal

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.PortService
import _SDOPackage.NameValue
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.Connection
import org.rtcoord.ConnectorSnapshot
import org.rtcoord.NotFoundException

/**
 * The remote calls a [org.rtcoord.Port] makes: connecting, reading its connections and disconnecting. [owner] is its
 * component, whose profile is read again (as [ownerSubject]) when the port's reference is not at hand.
 */
internal class PortCalls(
    private val core: TreeCore,
    private val subject: String,
    private val owner: ComponentObject,
    private val ownerSubject: String,
    private val name: String,
) {
    /** The port's object reference. */
    suspend fun reference(): PortService =
        owner.port(ownerSubject, name) ?: throw NotFoundException(subject, "no such port")

    /**
     * Connects this port to [others] with [properties] under [connectorName] and [id] (empty: the component chooses);
     * returns the connector as the port made it.
     */
    suspend fun connect(
        others: List<PortCalls>,
        properties: Map<String, String>,
        connectorName: String,
        id: String,
        othersNamed: String,
    ): ConnectorSnapshot {
        val references = listOf(reference()) + others.map { it.reference() }
        val holder =
            ConnectorProfileHolder(
                ConnectorProfile(
                    connectorName,
                    id,
                    references.toTypedArray(),
                    properties
                        .map { (key, value) ->
                            NameValue(key, core.orb.orb.create_any().apply { insert_string(value) })
                        }
                        .toTypedArray(),
                )
            )
        core.remote
            .call(subject, "connect") { references.first().connect(holder) }
            .orFail(subject, "connect", "to $othersNamed")
        val made = holder.value
        return ConnectorSnapshot(made.connector_id, made.name, made.properties.toMap())
    }

    /** The port's connections, each with its ports resolved to tree paths where the tree knows them. */
    suspend fun connections(): List<Connection> = coroutineScope {
        val port = reference()
        val profiles = core.remote.call(subject, "get_connector_profiles") { port.get_connector_profiles() }
        profiles
            .map { profile ->
                async {
                    Connection(
                        profile.connector_id,
                        profile.name,
                        profile.properties.toMap(),
                        profile.ports.map { peer -> async { describe(peer) } }.awaitAll(),
                    )
                }
            }
            .awaitAll()
    }

    private suspend fun describe(peer: PortService): Connection.End {
        val profile =
            runCatching { core.remote.call(subject, "get_port_profile") { peer.get_port_profile() } }.getOrNull()
                ?: return Connection.End("?", null)
        val owner = profile.owner?.let { core.components.objectFor(it) }
        val instance = profile.name.substringBefore('.')
        val path = owner?.knownPaths?.firstOrNull()?.withPort(profile.name.removePrefix("$instance."))
        return Connection.End(profile.name, path)
    }

    /** The ids of the port's connections, read now. */
    suspend fun connectorIds(): Set<String> {
        val port = reference()
        return core.remote
            .call(subject, "get_connector_profiles") { port.get_connector_profiles() }
            .map { it.connector_id }
            .toSet()
    }

    /** Removes connection [connectorId]; returns the components at its other ends (those that answer). */
    suspend fun disconnect(connectorId: String): List<ComponentObject> {
        val port = reference()
        val profile = core.remote.call(subject, "get_connector_profile") { port.get_connector_profile(connectorId) }
        val peers = coroutineScope { profile.ports.map { async { ownerOf(it) } }.awaitAll() }.filterNotNull()
        core.remote
            .call(subject, "disconnect") { port.disconnect(connectorId) }
            .orFail(subject, "disconnect", "connector '$connectorId'")
        return peers
    }

    /** The component owning [peer], if it answers. */
    private suspend fun ownerOf(peer: PortService): ComponentObject? = runCatching {
        core.remote.call(subject, "get_port_profile") { peer.get_port_profile() }
    }
        .getOrNull()
        ?.owner
        ?.let { core.components.objectFor(it) }
}
