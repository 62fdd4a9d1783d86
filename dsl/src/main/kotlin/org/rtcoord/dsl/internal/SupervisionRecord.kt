package org.rtcoord.dsl.internal

import kotlinx.coroutines.flow.toList
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.Connection
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerNode
import org.rtcoord.NodeFilters
import org.rtcoord.NodeKind
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree

/**
 * What a supervisor keeps of its [children] for recovering them: each one's type, name, hosting managers and active
 * configuration set (in the child), and the [connections] among them and to the rest of the system, taken when
 * supervision starts and kept up to date with their events. Used under the supervisor's lock.
 */
internal class SupervisionRecord(
    private val tree: RtcTree,
    private val children: List<SupervisedChild>,
    private val log: RecoveryLog,
) {
    /** The connections to make again when one of their supervised components is re-created. */
    val connections: MutableList<RecordedConnection> = mutableListOf()

    /** Records everything about every child, as the system is now. */
    suspend fun takeAll() {
        val managers = managers()
        children.forEach { take(it, managers) }
        children.forEach { child ->
            child.node
                .snapshot()
                .ports
                .filter { it.connectors.isNotEmpty() }
                .forEach { takeConnections(child, it.name) }
        }
    }

    /** Records [child]'s type, name, hosting managers (among [managers]) and active configuration set. */
    private suspend fun take(child: SupervisedChild, managers: List<ManagerNode>) {
        val node = child.node
        val snapshot = node.snapshot()
        child.typeName = snapshot.typeName
        child.instanceName = snapshot.instanceName
        val configuration = node.configuration()
        child.configuration =
            configuration.activeSet?.let { id -> configuration.sets[id]?.let { RecordedConfiguration(id, it) } }
        val host = managers.firstOrNull { manager ->
            val hosted =
                try {
                    manager.children()
                } catch (e: RtcException) {
                    emptyList()
                }
            hosted.any { it is ComponentNode && it.isSameComponent(node) }
        }
        child.managers = host?.let { managersAbove(it.path.child(node.name)) }.orEmpty()
        if (host == null) log.line("no manager hosts ${node.path}: it can be reset, not re-created")
    }

    /** Records that [child] was re-created as [node] through the manager at [manager]. */
    suspend fun recreated(child: SupervisedChild, node: ComponentNode, manager: RtcPath) {
        child.instanceName = node.snapshot().instanceName
        child.managers = (managersAbove(manager) + child.managers).distinctBy { it.path }
    }

    /** Records [child] anew, re-created by someone else: as it is now, wherever it is hosted now. */
    suspend fun retake(child: SupervisedChild) {
        take(child, managers())
    }

    private suspend fun managers(): List<ManagerNode> =
        tree.find(predicate = NodeFilters.kind(NodeKind.MANAGER)).toList().filterIsInstance<ManagerNode>()

    /** The managers above [path] (a component below a manager, a slave below its master), nearest first. */
    private suspend fun managersAbove(path: RtcPath): List<ManagerNode> =
        generateSequence(path.parent) { it.parent }
            .takeWhile { it.names.isNotEmpty() }
            .toList()
            .mapNotNull { above ->
                try {
                    tree.node(above) as? ManagerNode
                } catch (e: RtcException) {
                    null
                }
            }

    /** Records the connections of [child]'s port [port] that are not recorded yet ([only] that one, when given). */
    private suspend fun takeConnections(child: SupervisedChild, port: String, only: String? = null) {
        for (connection in child.node.port(port).connections()) {
            if ((only != null && connection.id != only) || connections.any { it.id == connection.id }) continue
            val ends = connection.ports.map { end -> endOf(end) }
            if (ends.any { it == null }) {
                log.line(
                    "connection ${connection.name} has a port the tree does not know (${connection.ports.joinToString { it.fullName }}): it will not be made again"
                )
                continue
            }
            val recorded =
                RecordedConnection(connection.id, connection.name, connection.properties, ends.filterNotNull())
            // One between the same ports went with a component since re-created: this one replaces it.
            connections.removeAll { it.joinsSamePorts(recorded) }
            connections += recorded
            log.line("recorded connection $recorded")
        }
    }

    private suspend fun endOf(end: Connection.End): RecordedConnection.End? {
        val path = end.path ?: return null
        val port = path.port ?: return null
        val component = path.withPort(null)
        val owner =
            children.firstOrNull { it.node.path == component }
                ?: try {
                        tree.component(component.toString())
                    } catch (e: RtcException) {
                        null
                    }
                    ?.let { node -> children.firstOrNull { it.node.isSameComponent(node) } }
        return owner?.let { RecordedConnection.End.Supervised(it, port) } ?: RecordedConnection.End.External(path)
    }

    /** Keeps [child]'s records up to date with [event]. */
    suspend fun update(child: SupervisedChild, event: RtcEvent) {
        when (event) {
            is PortConnected ->
                if (connections.none { it.id == event.connector.id })
                    takeConnections(child, event.port, only = event.connector.id)
            is PortDisconnected -> {
                val connection = connections.firstOrNull { it.id == event.connector.id } ?: return
                // A connection lost because one of its components failed or exits (it leaves its execution
                // contexts first, so it reads as CREATED) is made again with it; one removed while all its
                // components run normally was removed on purpose.
                if (connection.children.all { (it.status() as? ChildStatus.Up)?.state in RUNNING }) {
                    connections -= connection
                    log.line("connection $connection was removed: it will not be made again")
                }
            }
            is ConfigurationSetActivated -> {
                // None active is a passing state (a set was written and is about to be activated): keep the record.
                val set = event.new ?: return
                val values = child.node.snapshot().configuration?.sets?.get(set) ?: return
                child.configuration = RecordedConfiguration(set, values)
                log.line("${child.node.path} runs configuration set $set")
            }
            is ParameterChanged -> {
                val recorded = child.configuration?.takeIf { it.set == event.set } ?: return
                child.configuration =
                    recorded.copy(
                        values =
                            event.new?.let { recorded.values + (event.name to it) } ?: (recorded.values - event.name)
                    )
            }
            else -> Unit
        }
    }

    private companion object {
        /** The states of a component that works normally, active or not. */
        val RUNNING = setOf(LifeCycle.ACTIVE, LifeCycle.INACTIVE)
    }
}
