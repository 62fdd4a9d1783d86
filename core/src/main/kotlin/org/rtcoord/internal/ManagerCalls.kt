package org.rtcoord.internal

import RTC.RTObject
import RTC.ReturnCode_t
import RTM.Manager
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.TimedOutException
import org.rtcoord.UnreachableException

/**
 * The remote calls a [org.rtcoord.ManagerNode] makes on its manager ([ref]) and on that manager's slaves, as [subject]:
 * listings, creation and deletion, modules, profile.
 */
internal class ManagerCalls(private val core: TreeCore, private val subject: String, private val ref: Manager) {
    suspend fun slaves(): List<Manager> =
        core.remote.call(subject, "get_slave_managers") { ref.get_slave_managers() }.toList()

    suspend fun components(): List<RTObject> =
        core.remote.call(subject, "get_components") { ref.get_components() }.toList()

    /** [slave]'s name, or null when it does not answer (its process died). */
    suspend fun nameOf(slave: Manager): String? =
        try {
            nameOf(core.remote.call(subject, "get_profile") { slave.get_profile() }.properties.toMap())
        } catch (e: TimedOutException) {
            null
        } catch (e: UnreachableException) {
            null
        }

    /** The components [slave] hosts, or null when it does not answer. */
    suspend fun componentsOf(slave: Manager): List<RTObject>? = reachable {
        core.remote.call(subject, "get_components") { slave.get_components() }.toList()
    }

    suspend fun profile(): Map<String, String> =
        core.remote.call(subject, "get_profile") { ref.get_profile() }.properties.toMap()

    suspend fun isMaster(): Boolean = core.remote.call(subject, "is_master") { ref.is_master() }

    /** Asks the manager to create a component from [spec] (`type?key=value&...`); null when it created none. */
    suspend fun create(spec: String): RTObject? =
        core.remote.call(subject, "create_component") { ref.create_component(spec) }

    suspend fun delete(instanceName: String) {
        core.remote
            .call(subject, "delete_component") { ref.delete_component(instanceName) }
            .orFail(subject, "delete '$instanceName'")
    }

    /** Loads module [path]; false when the manager refuses it as BAD_PARAMETER (it has no such module). */
    suspend fun loadModule(path: String, initFunction: String): Boolean =
        accepted(
            core.remote.call(subject, "load_module") { ref.load_module(path, initFunction) },
            "load module '$path'",
        )

    /** Unloads module [path]; false when the manager refuses it as BAD_PARAMETER (it has not loaded it). */
    suspend fun unloadModule(path: String): Boolean =
        accepted(core.remote.call(subject, "unload_module") { ref.unload_module(path) }, "unload module '$path'")

    private fun accepted(code: ReturnCode_t, operation: String): Boolean {
        if (code == ReturnCode_t.BAD_PARAMETER) return false
        code.orFail(subject, operation)
        return true
    }

    suspend fun loadableModules(): List<Map<String, String>> =
        core.remote.call(subject, "get_loadable_modules") { ref.get_loadable_modules() }.map { it.properties.toMap() }

    suspend fun loadedModules(): List<Map<String, String>> =
        core.remote.call(subject, "get_loaded_modules") { ref.get_loaded_modules() }.map { it.properties.toMap() }

    suspend fun factories(): List<Map<String, String>> =
        core.remote.call(subject, "get_factory_profiles") { ref.get_factory_profiles() }.map { it.properties.toMap() }

    /**
     * The instance names of the components this manager and its slaves host, read now. A slave that does not answer
     * hosts nothing any more (its process is gone), so its names are free again.
     */
    suspend fun hostedInstanceNames(): Set<String> = coroutineScope {
        val own = async {
            core.remote
                .call(subject, "get_component_profiles") { ref.get_component_profiles() }
                .map { it.instance_name }
        }
        val slaves =
            slaves().map { slave ->
                async {
                    reachable {
                        core.remote
                            .call(subject, "get_component_profiles") { slave.get_component_profiles() }
                            .map { it.instance_name }
                    }
                        .orEmpty()
                }
            }
        (own.await() + slaves.awaitAll().flatten()).toSet()
    }

    companion object {
        /** [read]'s result, or null if the object did not answer: its process is gone. */
        suspend fun <T> reachable(read: suspend () -> T): T? =
            try {
                read()
            } catch (e: UnreachableException) {
                null
            }

        /**
         * A manager's name from its profile: its instance name, else its name, else `manager`. rtctree (and so rtls)
         * names a slave by `name` instead, but an OpenRTM-aist C++ slave carries its master's `manager.name` (it finds
         * the master by it, `ManagerServant::findManager`), so by `name` every C++ slave of a master would have one
         * path: the slave a master starts in place of a killed one would take the dead one's, and re-creating through
         * the master fails there.
         */
        fun nameOf(profile: Map<String, String>): String =
            profile["instance_name"]?.takeIf { it.isNotBlank() }
                ?: profile["name"]?.takeIf { it.isNotBlank() }
                ?: "manager"
    }
}
