package org.rtcoord.profile.internal

import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.toList
import org.rtcoord.ComponentNode
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree

/**
 * The manager topology a profile records as properties of its system element, since the schema has no place for
 * managers and a simulator needs them (rtcoord's `sim` module reads them, `ProfileKeys`):
 *
 * - `rtcoord.manager`: the first master manager bound below the saved path (`host:port/ctx.host_cxt/manager.mgr`);
 * - `rtcoord.manager.types`: every type it can create, through its slaves (their factories and the types of the modules
 *   they can load) and itself;
 * - `rtcoord.manager.components`: the saved components the master hosts itself, if any;
 * - `rtcoord.manager.command`: what the master runs to start a slave when none can create a type
 *   (`manager.modules.<language>.manager_cmd`), if it has a command;
 * - per slave, in the master's order, numbered from 1: `rtcoord.slave.N.name` (its instance name, as the tree names
 *   it), `rtcoord.slave.N.components` (the saved components it hosts), `rtcoord.slave.N.types` (the types it has
 *   factories for) and `rtcoord.slave.N.loadable` (the types of the modules it can load that it has no factory for
 *   yet).
 *
 * Lists are separated by commas. Composite types, which every manager registers, are left out. A slave whose process
 * died (it does not answer) is left out: its components are gone with it.
 */
internal class ManagerCapture(private val tree: RtcTree) {
    suspend fun properties(below: RtcPath, saved: Set<String>): Map<String, String> = coroutineScope {
        val master =
            tree
                .find(below) { it is ManagerNode && it.path.names.lastOrNull()?.endsWith(".mgr") == true }
                .toList()
                .firstOrNull() as ManagerNode? ?: return@coroutineScope emptyMap()
        val children = master.children()
        val slaves =
            children.filterIsInstance<ManagerNode>().map { slave ->
                async {
                    try {
                        Slave.read(slave, saved)
                    } catch (e: RtcException) {
                        null
                    }
                }
            }
        val types = async { master.factories().creatableTypes() }
        val profile = async { master.profile() }
        val own = hosted(children, saved)
        buildMap {
            put("rtcoord.manager", master.path.toString().removePrefix("/"))
            val read = slaves.awaitAll().filterNotNull()
            put("rtcoord.manager.types", (types.await() + read.flatMap { it.loadable }).distinct().joinToString(","))
            if (own.isNotEmpty()) put("rtcoord.manager.components", own.joinToString(","))
            val command = profile.await().let { it["modules.${it["language"]}.manager_cmd"] }
            if (!command.isNullOrBlank()) put("rtcoord.manager.command", command)
            read.forEachIndexed { index, slave ->
                val key = "rtcoord.slave.${index + 1}"
                put("$key.name", slave.name)
                put("$key.components", slave.components.joinToString(","))
                put("$key.types", slave.types.joinToString(","))
                put("$key.loadable", slave.loadable.joinToString(","))
            }
        }
    }

    /** What one slave hosts and can create. */
    private class Slave(
        val name: String,
        val components: List<String>,
        val types: List<String>,
        val loadable: List<String>,
    ) {
        companion object {
            suspend fun read(slave: ManagerNode, saved: Set<String>): Slave = coroutineScope {
                val factories = async { slave.factories().creatableTypes() }
                val modules = async { slave.loadableModules().creatableTypes() }
                val components = hosted(slave.children(), saved)
                val types = factories.await()
                Slave(slave.name, components, types, modules.await().filter { it !in types })
            }
        }
    }

    private companion object {
        /**
         * The instance names of the saved components among a manager's [children] (a manager lists each as
         * `<instance>.rtc`).
         */
        fun hosted(children: List<Node>, saved: Set<String>): List<String> =
            children.filterIsInstance<ComponentNode>().map { it.name.removeSuffix(".rtc") }.filter { it in saved }

        /** The type names of factory or module profiles, without the composite types every manager registers. */
        fun List<Map<String, String>>.creatableTypes(): List<String> = filterNot {
            it["category"].orEmpty().startsWith("composite.")
        }
            .mapNotNull { it["type_name"] ?: it["implementation_id"] }
            .distinct()
    }
}
