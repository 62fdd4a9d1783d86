package org.rtcoord

import RTM.Manager
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.idl.ObjectIdentity
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.ManagerCalls
import org.rtcoord.internal.ManagerCalls.Companion.reachable
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.pollUntil

/**
 * An OpenRTM manager daemon. Its children are its slave managers and the components it hosts itself (the same
 * components its naming context shows, as the same live objects); a master's own list of components includes its
 * slaves', which are shown below the slaves only. A master forwards creation to a slave; deletion goes to whichever
 * manager hosts the component.
 */
public sealed class ManagerNode(
    path: RtcPath,
    core: TreeCore,
    @get:JvmSynthetic internal val ref: Manager,
    private val namingParent: NamingDirectory?,
    /** The master this slave was listed under, if any. */
    private val master: ManagerNode? = null,
) : DirectoryNode(path, core) {
    private val subject: String
        get() = path.toString()

    /** Where its remote calls are made. */
    private val calls: ManagerCalls
        get() = ManagerCalls(core, subject, ref)

    override val kind: NodeKind
        get() = NodeKind.MANAGER

    @JvmSynthetic
    override suspend fun readChildren(previous: List<Node>, kept: (Node) -> Boolean): List<Node> = coroutineScope {
        val calls = calls
        val slaves = async { calls.slaves() }
        val hosted = async { calls.components() }
        val slaveListings =
            slaves
                .await()
                .map { slave ->
                    async {
                        // A slave whose process died has no name to show: it is left out, not the whole listing.
                        val slaveName = async { calls.nameOf(slave) }
                        val components = async { calls.componentsOf(slave) }
                        val name = slaveName.await() ?: return@async null
                        val node =
                            previous.filterIsInstance<ManagerNode>().firstOrNull {
                                it.name == name && ObjectIdentity.same(it.ref, slave)
                            } ?: ManagerNodeImpl(path.child(name), core, slave, null, this@ManagerNode)
                        // The master's listing says where they run: known before the slave's own listing is read.
                        node to
                            components.await().orEmpty().map { core.components.objectFor(it).apply { hostedBy(node) } }
                    }
                }
                .awaitAll()
                .filterNotNull()
        val ofSlaves = slaveListings.flatMap { it.second }.toSet()
        val before = previous.filterIsInstance<ComponentNode>().associateBy { it.component }
        val componentNodes =
            hosted
                .await()
                .map { core.components.objectFor(it) }
                .filter { it !in ofSlaves }
                .map { component ->
                    async {
                        component.hostedBy(this@ManagerNode)
                        // Listed but gone: it exited and its manager has not cleaned it up yet.
                        val name = "${reachable { component.instanceName(subject) } ?: return@async null}.rtc"
                        before[component]?.takeIf { it.name == name }
                            ?: ComponentNodeImpl(path.child(name), core, component)
                    }
                }
        slaveListings.map { it.first } + componentNodes.awaitAll().filterNotNull()
    }

    /** The manager's profile properties (`instance_name`, `pid`, ...). */
    @JvmSynthetic public suspend fun profile(): Map<String, String> = calls.profile()

    /** Whether it is a master manager. */
    @JvmSynthetic public suspend fun isMaster(): Boolean = calls.isMaster()

    /**
     * Creates a component of [type] (named [instanceName], or as the manager names it) with the given creation
     * [options], and returns it as a node, placed where naming shows it when the tree knows that context, else below
     * the manager. The tree learns of it without a full re-read.
     *
     * The manager decides whether it can: it may load a module for the type, and a master places the component in one
     * of its slaves (a dead one is skipped) or starts one. When the manager creates none, the error names it with its
     * factories and loadable modules. A name still held by a component that exited is free once its manager has cleaned
     * it up, which this waits for.
     */
    @JvmSynthetic
    public suspend fun create(
        type: String,
        instanceName: String? = null,
        options: Map<String, String> = emptyMap(),
    ): ComponentNode {
        if (instanceName != null) awaitNameFree(type, instanceName)
        val settings = buildList {
            instanceName?.let { add("instance_name=$it") }
            options.filterKeys { it != "manager_name" }.forEach { (key, value) -> add("$key=$value") }
            options["manager_name"]?.let { add("manager_name=$it") }
        }
        val spec = if (settings.isEmpty()) type else "$type?${settings.joinToString("&")}"
        val created =
            calls.create(spec)
                ?: throw OperationFailedException(
                    subject,
                    "create '$spec'",
                    "nil",
                    "the manager created none; ${whatItCanCreate()}",
                )
        val component = core.components.objectFor(created)
        val name = "${component.refresh(subject).instanceName}.rtc"
        namingParent?.let { parent ->
            (parent.child(name) as? ComponentNode)
                ?.takeIf { it.component === component }
                ?.let {
                    relist()
                    return it
                }
        }
        return relist().filterIsInstance<ComponentNode>().firstOrNull { it.component === component }
            ?: findBelowSlaves(component)
            ?: ComponentNodeImpl(path.child(name), core, component)
    }

    /**
     * Refuses [instanceName] if a live component holds it; waits while only an exited one does (its manager still lists
     * it until its next clean-up, and would hand back the dead component).
     */
    private suspend fun awaitNameFree(type: String, instanceName: String) {
        val deadline = core.time.markNow() + core.remote.defaultDeadline
        pollUntil(deadline, 20.milliseconds) {
            when {
                instanceName !in calls.hostedInstanceNames() -> Unit
                hostOf(instanceName)?.second?.let { answers(it) } == true ->
                    throw BadParameterException(
                        subject,
                        "create '$type'",
                        "a component named '$instanceName' exists already",
                    )
                else -> null
            }
        }
            ?: throw TimedOutException(
                subject,
                "create '$type' (the name '$instanceName' is still held by a component that exited)",
                core.remote.defaultDeadline.inWholeMilliseconds,
            )
    }

    /**
     * The types this manager has factories for, each once (a master lists the composite type every manager registers
     * once for itself and once per slave), and the modules it could load.
     */
    private suspend fun whatItCanCreate(): String = coroutineScope {
        val types = async { factories().mapNotNull { it["implementation_id"] ?: it["type_name"] }.distinct().sorted() }
        val modules = async {
            loadableModules().mapNotNull { it["module_file_name"] ?: it["module_file_path"] }.distinct().sorted()
        }
        "factories: ${types.await().joinToString().ifEmpty { "none" }}; loadable modules: ${modules.await().joinToString().ifEmpty { "none" }}"
    }

    /**
     * Deletes component [instanceName] through the manager (this one or a slave) that hosts it, and returns once it has
     * gone from naming too (its manager unbinds it shortly after the component exits).
     */
    @JvmSynthetic
    public suspend fun delete(instanceName: String) {
        val (owner, node) =
            hostOf(instanceName)
                ?: throw NotFoundException(
                    subject,
                    "no component '$instanceName' is hosted by this manager or its slaves",
                )
        owner.calls.delete(instanceName)
        // The component's objects are gone now: its absence from the listings is the delete's success.
        owner.relist()
        if (owner !== this) relist()
        val bound =
            topMaster().namingParent?.let { parent ->
                (parent.child(node.name) as? ComponentNode)?.takeIf { it.component === node.component }
            }
        (bound ?: node).awaitUnbound("delete '$instanceName'")
    }

    /** Loads module [path] (calling [initFunction] in it, if the manager needs one). */
    @JvmSynthetic
    public suspend fun loadModule(path: String, initFunction: String = "") {
        if (!calls.loadModule(path, initFunction)) {
            val loadable = loadableModules().mapNotNull { it["module_file_name"] ?: it["module_file_path"] }.sorted()
            throw BadParameterException(
                subject,
                "load module '$path'",
                "BAD_PARAMETER (loadable: ${loadable.joinToString().ifEmpty { "none" }})",
            )
        }
    }

    /** Unloads module [path]. */
    @JvmSynthetic
    public suspend fun unloadModule(path: String) {
        if (!calls.unloadModule(path)) {
            val loaded = loadedModules().mapNotNull { it["file_path"] ?: it["module_file_path"] }.sorted()
            throw BadParameterException(
                subject,
                "unload module '$path'",
                "BAD_PARAMETER (loaded: ${loaded.joinToString().ifEmpty { "none" }})",
            )
        }
    }

    /** Modules the manager could load, as their profile properties. */
    @JvmSynthetic public suspend fun loadableModules(): List<Map<String, String>> = calls.loadableModules()

    /** Modules the manager has loaded. */
    @JvmSynthetic public suspend fun loadedModules(): List<Map<String, String>> = calls.loadedModules()

    /** The component types the manager can create, as their factory profiles. */
    @JvmSynthetic public suspend fun factories(): List<Map<String, String>> = calls.factories()

    /** The manager hosting [instanceName] and the component as it lists it. */
    private suspend fun hostOf(instanceName: String): Pair<ManagerNode, ComponentNode>? {
        val hosts = listOf(this) + children().filterIsInstance<ManagerNode>()
        return hosts.firstNotNullOfOrNull { manager ->
            // Below a manager a component is named after its instance name.
            manager
                .relist()
                .firstOrNull { it is ComponentNode && it.name == "$instanceName.rtc" }
                ?.let { manager to it as ComponentNode }
        }
    }

    /** Whether [node]'s object still exists: an exited component's does not, though its manager may list it a while. */
    private suspend fun answers(node: ComponentNode): Boolean = reachable { !node.calls.nonExistent() } ?: false

    private fun topMaster(): ManagerNode = master?.topMaster() ?: this

    private suspend fun findBelowSlaves(component: ComponentObject): ComponentNode? =
        children().filterIsInstance<ManagerNode>().firstNotNullOfOrNull { slave ->
            slave.relist().filterIsInstance<ComponentNode>().firstOrNull { it.component === component }
        }
}

/** The [ManagerNode]s the tree makes ([Node] says why that class is sealed). */
internal class ManagerNodeImpl(
    path: RtcPath,
    core: TreeCore,
    ref: Manager,
    namingParent: NamingDirectory?,
    master: ManagerNode? = null,
) : ManagerNode(path, core, ref, namingParent, master)
