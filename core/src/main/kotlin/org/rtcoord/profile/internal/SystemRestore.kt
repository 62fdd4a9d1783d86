package org.rtcoord.profile.internal

import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.ComponentNode
import org.rtcoord.ContextSelector
import org.rtcoord.NotFoundException
import org.rtcoord.Port
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.ZombieNode
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfileRefusedException
import org.rtcoord.profile.RestoreReport
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent

/**
 * A profile's components resolved on the live system, each read afresh: a tree that has lived a while (a coordinator's)
 * may hold snapshots older than the system, and a restore or check must not go by them.
 */
internal class ResolvedSystem(
    val profile: RtsProfile,
    val nodes: Map<String, ComponentNode>,
    val missing: List<ProfileComponent>,
) {
    fun node(target: TargetComponent): ComponentNode? = profile.component(target)?.let { nodes[it.instanceName] }

    companion object {
        suspend fun of(tree: RtcTree, profile: RtsProfile): ResolvedSystem = coroutineScope {
            val found = profile.components.map { c -> async { c to find(tree, c) } }.awaitAll()
            ResolvedSystem(
                profile,
                found.mapNotNull { (c, n) -> n?.let { c.instanceName to it } }.toMap(),
                found.filter { it.second == null }.map { it.first },
            )
        }

        private suspend fun find(tree: RtcTree, c: ProfileComponent): ComponentNode? =
            try {
                tree.component("/" + c.pathUri.removePrefix("/")).also { it.refresh() }
            } catch (e: NotFoundException) {
                null
            } catch (e: RtcException) {
                // A dead registration is as good as missing: there is no component to restore onto.
                if (runCatching { tree.node("/" + c.pathUri.removePrefix("/")) }.getOrNull() is ZombieNode) null
                else throw e
            }
    }
}

/** Restores a profile onto the running system: checks everything first, then changes what differs. */
internal class SystemRestore(private val tree: RtcTree) {
    private class PlannedConnection(
        val connector: PortConnector,
        val from: Port,
        val to: Port,
        val properties: Map<String, String>,
    )

    /**
     * Restores [profile]; with [createMissing], its missing components are created first, and deleted again if the
     * restore is then refused, so that a refusal still leaves the system as it was. With [strict], a value outside its
     * constraint refuses the restore; without, it is a warning.
     */
    suspend fun restore(profile: RtsProfile, createMissing: Boolean, strict: Boolean): RestoreReport {
        val found = ResolvedSystem.of(tree, profile)
        if (!createMissing || found.missing.isEmpty()) return restore(found, emptyList(), strict)
        val creation = MissingComponentCreation(tree)
        val planned = creation.plan(found.missing)
        val made = mutableListOf<MissingComponentCreation.Planned>()
        val lines = mutableListOf<String>()
        try {
            for (p in planned) {
                lines += creation.create(p)
                made += p
            }
            val report = restore(ResolvedSystem.of(tree, profile), lines, strict)
            return report.created(made.map { it.path })
        } catch (e: ProfileRefusedException) {
            val undone =
                made.reversed().mapNotNull { p ->
                    try {
                        creation.delete(p)
                        null
                    } catch (d: RtcException) {
                        "${p.path} (${d.reason})"
                    }
                }
            val after =
                if (undone.isEmpty()) "the components created for it were deleted again"
                else "could not delete again ${undone.joinToString()}"
            throw ProfileRefusedException(if (made.isEmpty()) e.reason else "${e.reason}; $after")
        }
    }

    private suspend fun restore(system: ResolvedSystem, created: List<String>, strict: Boolean): RestoreReport {
        val profile = system.profile
        system.missing
            .firstOrNull { it.isRequired }
            ?.let {
                throw ProfileRefusedException("required component /${it.pathUri.removePrefix("/")} is not running")
            }
        val kept = mutableListOf<String>()
        val connections =
            (profile.dataPortConnectors + profile.servicePortConnectors).mapNotNull { plan(system, it, kept) }
        val warnings = mutableListOf<String>()
        for (c in profile.components) {
            val node = system.nodes[c.instanceName] ?: continue
            val configuration = node.configuration()
            ConfigurationRestore.problem(c, configuration, strict)?.let {
                throw ProfileRefusedException("${node.path}: $it")
            }
            warnings += ConfigurationRestore.constraintWarnings(c, configuration).map { "${node.path}: $it" }
            for (ec in c.executionContexts) {
                val handle =
                    ec.id.toIntOrNull()
                        ?: throw ProfileRefusedException(
                            "${node.path}: execution context id '${ec.id}' is not a number"
                        )
                if (node.snapshot().context(handle) == null)
                    throw ProfileRefusedException("${node.path}: no execution context $handle")
            }
        }
        val done = created.toMutableList()
        for (c in connections) {
            c.from.connect(listOf(c.to), c.properties, c.connector.name.ifEmpty { null }, c.connector.connectorId)
            done += "connected ${c.from.path} to ${c.to.path}"
        }
        for (c in profile.components) {
            val node = system.nodes[c.instanceName] ?: continue
            done += ConfigurationRestore.apply(node, c).map { "${node.path}: $it" }
            for (ec in c.executionContexts) {
                val rate = ec.rate ?: continue
                val handle = ec.id.toInt()
                if (node.snapshot().context(handle)?.rate == rate) continue
                node.executionContext(ContextSelector.Handle(handle)).setRate(rate)
                done += "${node.path}: execution context $handle at $rate Hz"
            }
        }
        return RestoreReport(done, kept, system.missing.map { "/" + it.pathUri.removePrefix("/") }, warnings = warnings)
    }

    /** The connection to make, null when it is there already or an end is an optional missing component. */
    private suspend fun plan(
        system: ResolvedSystem,
        connector: PortConnector,
        kept: MutableList<String>,
    ): PlannedConnection? {
        val fromNode = system.node(connector.source)
        val toNode = system.node(connector.target)
        if (fromNode == null || toNode == null) {
            val missing = listOf(connector.source, connector.target).first { system.node(it) == null }
            if (system.profile.component(missing)?.isRequired != false)
                throw ProfileRefusedException("connector '${connector.name}': no component ${missing.instanceName}")
            return null
        }
        val from = port(fromNode, connector.source)
        val to = port(toNode, connector.target)
        val wanted = connector.connectionProperties()
        val existing = from.connections()
        val same = existing.firstOrNull { c ->
            c.ports.any { it.fullName == "${toNode.snapshot().instanceName}.${to.name}" }
        }
        val clash = existing.firstOrNull {
            it.id == connector.connectorId && connector.connectorId.isNotEmpty() && it !== same
        }
        if (clash != null)
            throw ProfileRefusedException(
                "${from.path}: connector id '${connector.connectorId}' is already used by another connection"
            )
        if (same != null) {
            val differs = wanted.filter { (k, v) ->
                k.startsWith("dataport.") && same.properties[k] != null && same.properties[k] != v
            }
            if (differs.isNotEmpty()) {
                throw ProfileRefusedException(
                    "${from.path} and ${to.path} are connected with ${differs.keys.joinToString { "$it=${same.properties[it]}" }}, the profile wants ${differs.entries.joinToString { "${it.key}=${it.value}" }}"
                )
            }
            kept += "${from.path} to ${to.path}"
            return null
        }
        val properties =
            try {
                from.connectable(listOf(to), wanted)
            } catch (e: RtcException) {
                throw ProfileRefusedException("cannot connect ${from.path} to ${to.path}: ${e.reason}")
            }
        return PlannedConnection(connector, from, to, properties)
    }

    private suspend fun port(node: ComponentNode, end: TargetComponent): Port {
        val name = end.shortPortName ?: throw ProfileRefusedException("${node.path}: a connector end names no port")
        if (node.snapshot().port(name) == null) throw ProfileRefusedException("${node.path}: no port '$name'")
        return node.port(name)
    }
}
