package org.rtcoord

import RTC.ReturnCode_t
import RTM.Manager
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.orFail
import org.rtcoord.internal.toMap

/**
 * An OpenRTM manager daemon. Its children are its slave managers and the components it hosts (the
 * same components its naming context shows, as the same live objects). A master forwards creation to
 * a slave; deletion goes to whichever manager hosts the component.
 */
public class ManagerNode internal constructor(
    path: RtcPath,
    core: TreeCore,
    internal val ref: Manager,
    private val namingParent: NamingDirectory?,
) : DirectoryNode(path, core) {
    private val subject: String get() = path.toString()

    override val kind: NodeKind get() = NodeKind.MANAGER

    override suspend fun readChildren(previous: List<Node>): List<Node> = coroutineScope {
        val slaves = async { core.remote.call(subject, "get_slave_managers") { ref.get_slave_managers() } }
        val hosted = async { core.remote.call(subject, "get_components") { ref.get_components() } }
        val slaveNodes = slaves.await().map { slave ->
            async {
                // A slave whose process died has no name to show: it is left out, not the whole listing.
                val profile = try {
                    core.remote.call(subject, "get_profile") { slave.get_profile() }
                } catch (e: UnreachableException) {
                    return@async null
                } catch (e: TimedOutException) {
                    return@async null
                }
                val name = nameOf(profile.properties.toMap())
                previous.filterIsInstance<ManagerNode>().firstOrNull { it.name == name && it.ref._is_equivalent(slave) }
                    ?: ManagerNode(path.child(name), core, slave, null)
            }
        }
        val componentNodes = hosted.await().map { rtc ->
            async {
                val component = core.components.objectFor(rtc).also { it.hostedBy(this@ManagerNode) }
                val name = "${component.instanceName(subject)}.rtc"
                previous.filterIsInstance<ComponentNode>().firstOrNull { it.component === component && it.name == name }
                    ?: ComponentNode(path.child(name), core, component)
            }
        }
        slaveNodes.awaitAll().filterNotNull() + componentNodes.awaitAll()
    }

    /** The manager's profile properties (`instance_name`, `pid`, ...). */
    public suspend fun profile(): Map<String, String> = core.remote.call(subject, "get_profile") { ref.get_profile() }.properties.toMap()

    /** Whether it is a master manager. */
    public suspend fun isMaster(): Boolean = core.remote.call(subject, "is_master") { ref.is_master() }

    /**
     * Creates a component of [type] (named [instanceName], or as the manager names it) with the given
     * creation [options], and returns it as a node, placed where naming shows it when the tree knows
     * that context, else below the manager. The tree learns of it without a full re-read.
     */
    public suspend fun create(type: String, instanceName: String? = null, options: Map<String, String> = emptyMap()): ComponentNode {
        val factories = factories().mapNotNull { it["implementation_id"] ?: it["type_name"] }
        if (factories.isNotEmpty() && type !in factories) {
            throw NotFoundException(subject, "no factory for component type '$type' (types: ${factories.sorted().joinToString()})")
        }
        if (instanceName != null && instanceName in hostedInstanceNames()) {
            throw BadParameterException(subject, "create '$type'", "a component named '$instanceName' exists already")
        }
        val settings = buildList {
            instanceName?.let { add("instance_name=$it") }
            options.filterKeys { it != "manager_name" }.forEach { (key, value) -> add("$key=$value") }
            options["manager_name"]?.let { add("manager_name=$it") }
        }
        val spec = if (settings.isEmpty()) type else "$type?${settings.joinToString("&")}"
        val created = core.remote.call(subject, "create_component") { ref.create_component(spec) }
            ?: throw OperationFailedException(subject, "create '$spec'", "nil", "the manager returned no component")
        val component = core.components.objectFor(created)
        val name = "${component.refresh(subject).instanceName}.rtc"
        namingParent?.let { parent ->
            (parent.child(name) as? ComponentNode)?.takeIf { it.component === component }?.let { relist(); return it }
        }
        return relist().filterIsInstance<ComponentNode>().firstOrNull { it.component === component }
            ?: findBelowSlaves(component)
            ?: ComponentNode(path.child(name), core, component)
    }

    /** Deletes component [instanceName] through the manager (this one or a slave) that hosts it. */
    public suspend fun delete(instanceName: String) {
        val owner = hostOf(instanceName) ?: throw NotFoundException(subject, "no component '$instanceName' is hosted by this manager or its slaves")
        core.remote.call(owner.subject, "delete_component") { owner.ref.delete_component(instanceName) }
            .orFail(owner.subject, "delete '$instanceName'")
        owner.relist()
        if (owner !== this) relist()
        namingParent?.relist()
    }

    /** Loads module [path] (calling [initFunction] in it, if the manager needs one). */
    public suspend fun loadModule(path: String, initFunction: String = "") {
        val code = core.remote.call(subject, "load_module") { ref.load_module(path, initFunction) }
        if (code == ReturnCode_t.BAD_PARAMETER) {
            val loadable = loadableModules().mapNotNull { it["module_file_name"] ?: it["module_file_path"] }.sorted()
            throw BadParameterException(subject, "load module '$path'", "BAD_PARAMETER (loadable: ${loadable.joinToString().ifEmpty { "none" }})")
        }
        code.orFail(subject, "load module '$path'")
    }

    /** Unloads module [path]. */
    public suspend fun unloadModule(path: String) {
        val code = core.remote.call(subject, "unload_module") { ref.unload_module(path) }
        if (code == ReturnCode_t.BAD_PARAMETER) {
            val loaded = loadedModules().mapNotNull { it["file_path"] ?: it["module_file_path"] }.sorted()
            throw BadParameterException(subject, "unload module '$path'", "BAD_PARAMETER (loaded: ${loaded.joinToString().ifEmpty { "none" }})")
        }
        code.orFail(subject, "unload module '$path'")
    }

    /** Modules the manager could load, as their profile properties. */
    public suspend fun loadableModules(): List<Map<String, String>> =
        core.remote.call(subject, "get_loadable_modules") { ref.get_loadable_modules() }.map { it.properties.toMap() }

    /** Modules the manager has loaded. */
    public suspend fun loadedModules(): List<Map<String, String>> =
        core.remote.call(subject, "get_loaded_modules") { ref.get_loaded_modules() }.map { it.properties.toMap() }

    /** The component types the manager can create, as their factory profiles. */
    public suspend fun factories(): List<Map<String, String>> =
        core.remote.call(subject, "get_factory_profiles") { ref.get_factory_profiles() }.map { it.properties.toMap() }

    /**
     * The instance names of the components this manager and its slaves host, read now. A slave that does
     * not answer hosts nothing any more (its process is gone), so its names are free again.
     */
    private suspend fun hostedInstanceNames(): Set<String> = coroutineScope {
        val own = async { core.remote.call(subject, "get_component_profiles") { ref.get_component_profiles() }.map { it.instance_name } }
        val slaves = core.remote.call(subject, "get_slave_managers") { ref.get_slave_managers() }.map { slave ->
            async {
                try {
                    core.remote.call(subject, "get_component_profiles") { slave.get_component_profiles() }.map { it.instance_name }
                } catch (e: UnreachableException) {
                    emptyList()
                }
            }
        }
        (own.await() + slaves.awaitAll().flatten()).toSet()
    }

    private suspend fun hostOf(instanceName: String): ManagerNode? {
        val hosts = listOf(this) + children().filterIsInstance<ManagerNode>()
        return hosts.firstOrNull { manager ->
            // Below a manager a component is named after its instance name.
            manager.relist().any { it is ComponentNode && it.name == "$instanceName.rtc" }
        }
    }

    private suspend fun findBelowSlaves(component: org.rtcoord.internal.ComponentObject): ComponentNode? =
        children().filterIsInstance<ManagerNode>().firstNotNullOfOrNull { slave ->
            slave.relist().filterIsInstance<ComponentNode>().firstOrNull { it.component === component }
        }

    private companion object {
        fun nameOf(profile: Map<String, String>): String =
            profile["instance_name"]?.takeIf { it.isNotBlank() } ?: profile["name"]?.takeIf { it.isNotBlank() } ?: "manager"
    }
}
