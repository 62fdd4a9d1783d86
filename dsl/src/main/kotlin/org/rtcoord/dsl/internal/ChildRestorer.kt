package org.rtcoord.dsl.internal

import org.rtcoord.BadParameterException
import org.rtcoord.ComponentNode
import org.rtcoord.ManagerNode
import org.rtcoord.OperationFailedException
import org.rtcoord.Port
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.dsl.portOf

/**
 * Brings a supervised component back when it is gone: re-creates it through the managers that hosted it, then restores
 * its configuration set and the connections the [record] holds for it.
 */
internal class ChildRestorer(
    private val engine: Engine,
    private val record: SupervisionRecord,
    private val log: RecoveryLog,
) {
    private val tree: RtcTree
        get() = engine.tree

    /**
     * Re-creates [child] through its managers and makes its names (and so whatever watches them) follow the new
     * component; returns it, or null if no manager made it. The caller then [restore]s it.
     */
    suspend fun recreate(child: SupervisedChild, reason: String): ComponentNode? {
        val old = child.node
        log.line("${old.path} is gone ($reason)")
        if (child.managers.isEmpty()) {
            log.line("re-create ${old.path} failed: no manager hosted it when it was first seen")
            return null
        }
        val created = child.managers.firstNotNullOfOrNull { createThrough(it, child) } ?: return null
        val node = placed(old, created)
        engine.identities.follow(old, node)
        record.recreated(child, node, created.path)
        log.line("re-created ${old.path} as ${node.path}")
        return node
    }

    /**
     * The component someone else re-created in place of [failed] (by hand, another tool), which [child]'s name refers
     * to from now on and is recorded as it is; null if its name still refers to [failed] and nothing replaced it. Asks
     * the run's [Identities], which may have followed it already.
     */
    suspend fun replacement(child: SupervisedChild, failed: ComponentNode): ComponentNode? {
        if (child.node.isSameComponent(failed)) engine.identities.successor(child.ref.selector, failed) ?: return null
        val node = child.node
        record.retake(child)
        log.line("${node.path} was re-created by someone else: following it")
        return node
    }

    /** Creates [child] anew through [manager]: with its old name, or one the manager chooses if it refuses that. */
    private suspend fun createThrough(manager: ManagerNode, child: SupervisedChild): ComponentNode? {
        val what = "re-create ${child.instanceName} (${child.typeName}) through ${manager.path}"
        log.line(what)
        return try {
            manager.create(child.typeName, child.instanceName)
        } catch (e: OperationFailedException) {
            // No component came back: the name may still be held by the old, unresponsive instance.
            log.line("$what failed: ${e.message}; trying a name the manager chooses")
            log.attempt("re-create ${child.typeName} through ${manager.path}") { manager.create(child.typeName) }
        } catch (e: RtcException) {
            log.line("$what failed: ${e.message}")
            null
        }
    }

    /** [created] as the naming context of [old] shows it (the path users know), else as its manager does. */
    private suspend fun placed(old: ComponentNode, created: ComponentNode): ComponentNode {
        val path = old.path.parent?.child(created.name) ?: return created
        return (tree.registeredAt(path) as? ComponentNode)?.takeIf { it.isSameComponent(created) } ?: created
    }

    /** Restores [child]'s recorded configuration set and makes its recorded connections again. */
    suspend fun restore(child: SupervisedChild) {
        restoreConfiguration(child)
        restoreConnections(child)
    }

    private suspend fun restoreConfiguration(child: SupervisedChild) {
        val recorded = child.configuration ?: return
        val node = child.node
        log.attempt("restore configuration set ${recorded.set} of ${node.path}") {
            val current = node.configuration()
            val values = current.sets[recorded.set]
            if (values == null) {
                node.addConfigurationSet(recorded.set, recorded.values)
            } else {
                recorded.values
                    .filter { (parameter, value) -> values[parameter] != value }
                    .forEach { (parameter, value) ->
                        log.line("set ${node.path} parameter $parameter=$value in ${recorded.set}")
                        node.setParameter(parameter, value, recorded.set)
                    }
            }
            if (current.activeSet != recorded.set) node.activateConfigurationSet(recorded.set)
        }
    }

    /** Makes [child]'s recorded connections again, each once all its supervised components are back. */
    private suspend fun restoreConnections(child: SupervisedChild) {
        for (connection in record.connections.filter { it.involves(child) }) {
            val away = connection.children.filter { it !== child }.firstOrNull { it.status() is ChildStatus.Gone }
            if (away != null) {
                log.line("reconnect $connection: waits until $away is back")
                continue
            }
            log.attempt("reconnect $connection") {
                val ports = connection.ends.map { portOf(it) }
                // Live ports still hold the connector to the dead component: it would stay beside the new one.
                connection.ends
                    .zip(ports)
                    .filter { (end, _) -> !(end is RecordedConnection.End.Supervised && end.child === child) }
                    .forEach { (_, port) -> removeStale(port, connection.id) }
                connection.id = ports.first().connect(ports.drop(1), connection.properties, connection.name).id
            }
        }
    }

    private suspend fun portOf(end: RecordedConnection.End): Port =
        when (end) {
            is RecordedConnection.End.Supervised -> end.child.node.port(end.port)
            is RecordedConnection.End.External -> tree.port(end.path.toString())
        }

    private suspend fun removeStale(port: Port, id: String) {
        if (port.connections().none { it.id == id }) return
        log.attempt("remove stale connector $id from ${port.path}") {
            try {
                port.disconnect(id)
            } catch (e: BadParameterException) {
                // Gone meanwhile: what this step wanted.
            }
        }
    }
}
