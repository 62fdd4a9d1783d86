package org.rtcoord.cli.serve

import kotlinx.serialization.Serializable
import org.rtcoord.cli.json.FsmJson

/**
 * The system below [top] as the page draws it ([NetworkView] makes it): naming contexts, components with their ports,
 * nodes outside the tree that connections reach, managers, zombies and connections. Every id is a whole path; states
 * are the tree's model's up to [sequence].
 */
@Serializable
internal data class NetworkJson(
    val top: String,
    val sequence: Long,
    val contexts: List<NamingContextJson>,
    val components: List<NetworkComponentJson>,
    /** Ends of connections that are not components below [top]. */
    val external: List<ExternalJson>,
    val managers: List<ManagerBoxJson>,
    val zombies: List<ZombieJson>,
    val connections: List<ConnectionLineJson>,
)

/**
 * A naming context or name server, drawn as a box around what it binds; [reachable] is false when it could not be
 * listed.
 */
@Serializable
internal data class NamingContextJson(val id: String, val name: String, val parent: String?, val reachable: Boolean)

/**
 * A component: its instance [name] and [type], the context it is bound in ([parent]), its overall [state] (a LifeCycle
 * name), the manager that hosts it, its FSM (null when it has none) and its ports.
 */
@Serializable
internal data class NetworkComponentJson(
    val id: String,
    val name: String,
    val type: String,
    val parent: String?,
    val state: String,
    val hostedBy: String?,
    val fsm: FsmJson?,
    val ports: List<NetworkPortJson>,
)

/**
 * A port where the page draws it ([kind] `in`, `out` or `service`), its data type, its interfaces as `provided name:
 * Type`.
 */
@Serializable
internal data class NetworkPortJson(
    val name: String,
    val kind: String,
    val dataType: String?,
    val interfaces: List<String>,
)

/** A connection's end outside the components drawn. */
@Serializable internal data class ExternalJson(val id: String, val name: String)

/** A manager, drawn in the naming context of its master ([parent]), with what it [hosts]: components and slaves. */
@Serializable
internal data class ManagerBoxJson(val id: String, val name: String, val parent: String?, val hosts: List<String>)

/** A registration whose object does not answer, and why. */
@Serializable internal data class ZombieJson(val id: String, val name: String, val parent: String?, val reason: String)

/** A connection from [source]'s [sourcePort] to [target]'s [targetPort]; [kind] `data` (directed) or `service`. */
@Serializable
internal data class ConnectionLineJson(
    val source: String,
    val target: String,
    val sourcePort: String,
    val targetPort: String,
    val label: String?,
    val kind: String,
)
