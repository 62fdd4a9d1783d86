package org.rtcoord.dsl

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.flow.toList
import org.rtcoord.AmbiguousNameException
import org.rtcoord.ComponentNode
import org.rtcoord.Connection
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.NodeFilters
import org.rtcoord.NodeFilters.and
import org.rtcoord.NodeKind
import org.rtcoord.NotFoundException
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.UnreachableException
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CopyOnWriteArrayList

/**
 * Resolves a script's references against the live tree and performs their actions, logging each. A
 * component found once is remembered; when it stops answering (re-created, moved), it is looked up again.
 */
internal class Engine(private val directory: Path = Paths.get("")) {
    lateinit var tree: RtcTree
    var log: (String) -> Unit = {}
    private val resolved = ConcurrentHashMap<String, ComponentNode>()

    fun componentRef(name: String) = ComponentRef(name, this)

    fun portRef(path: String): PortRef {
        val split = path.lastIndexOf(':')
        require(split > 0 && split < path.length - 1) { "not a port: '$path' (write component:port)" }
        return PortRef(componentRef(path.substring(0, split)), path.substring(split + 1), this)
    }

    fun reference(node: ComponentNode): ComponentRef = ComponentRef(node.path.toString(), this).also { resolved[node.path.toString()] = node }

    /** Told when references move to a re-created component, so that the rules watching it move too. */
    var followed: suspend (old: ComponentNode, new: ComponentNode) -> Unit = { _, _ -> }

    /** References that resolved to [old], a component since re-created as [new], resolve to [new] from now on. */
    suspend fun follow(old: ComponentNode, new: ComponentNode) {
        resolved.replaceAll { _, node -> if (node.isSameComponent(old)) new else node }
        followed(old, new)
    }

    fun portOf(port: Any): PortRef = when (port) {
        is PortRef -> port
        is String -> portRef(port)
        else -> throw IllegalArgumentException("not a port: $port (a port(...) or \"component:port\")")
    }

    /** The one component [selector] names. */
    suspend fun component(selector: String): ComponentNode {
        resolved[selector]?.let { return it }
        val node = when {
            selector.startsWith("/") || selector.startsWith("corbaloc:") -> tree.component(selector)
            selector.any { it == '*' || it == '?' } -> components(selector).singleOrNull()
                ?: throw AmbiguousNameException(selector, components(selector).map { it.path.toString() })
            else -> tree.componentNamed(selector)
        }
        return node.also { resolved[selector] = it }
    }

    /** Every component [selector] names: one for a name or path, any number for a pattern. */
    suspend fun components(selector: String): List<ComponentNode> {
        if (selector.none { it == '*' || it == '?' }) return listOf(component(selector))
        val pattern = if ('.' in selector) selector else "$selector.rtc"
        return tree.find(predicate = NodeFilters.kind(NodeKind.COMPONENT) and NodeFilters.name(pattern)).toList()
            .map { it as ComponentNode }
            .fold(emptyList()) { kept, node -> if (kept.any { it.isSameComponent(node) }) kept else kept + node }
    }

    suspend fun manager(ref: ManagerRef): ManagerNode {
        if (ref.selector.startsWith("/")) return tree.manager(ref.selector)
        val found = tree.find(predicate = NodeFilters.kind(NodeKind.MANAGER) and NodeFilters.name(ref.selector)).toList()
        return when (found.size) {
            1 -> found.single() as ManagerNode
            0 -> throw NotFoundException(ref.selector, "no such manager on ${tree.nameServers.joinToString { it.address }}")
            else -> throw AmbiguousNameException(ref.selector, found.map { it.path.toString() })
        }
    }

    /** Every action that failed so far, in order. */
    val failedActions: MutableList<FailedAction> = CopyOnWriteArrayList()

    /**
     * Runs [action] on [ref]'s component, logged as [what] (followed by the component's path, unless
     * [what] names its objects itself); once more after a fresh lookup if the component stopped answering.
     */
    suspend fun act(what: String, ref: ComponentRef, namesItself: Boolean = false, action: suspend (ComponentNode) -> Unit): Unit =
        actReversibly(what, ref, namesItself) { action(it); null }

    /**
     * [act], for an action that returns how to undo it: the handler's journal, if it runs in one,
     * records the action with its undo once it succeeded. A failure is recorded in [failedActions].
     */
    suspend fun actReversibly(what: String, ref: ComponentRef, namesItself: Boolean = false, action: suspend (ComponentNode) -> Undo?) {
        var line = what
        fun describe(node: ComponentNode) = (if (namesItself) what else "$what ${node.path}").also { line = it }
        val undo = recorded({ line }) {
            withComponent(ref.selector, { log(describe(it)) }, { log("${describe(it)} (looked up again)") }, action)
        }
        currentCoroutineContext()[ActionJournal]?.record(line, undo)
    }

    /** The RTSProfile in [file], relative to the script's directory; read anew at each call. */
    fun profile(file: String): RtsProfile = RtsProfiles.read(directory.resolve(file))

    /**
     * Runs [action], one on the whole system (a profile's restore), logged as [what] and journaled
     * without an undo; its failure is recorded as the others' are.
     */
    suspend fun <T> perform(what: String, action: suspend () -> T): T {
        log(what)
        return recorded({ what }, action).also { currentCoroutineContext()[ActionJournal]?.record(what, null) }
    }

    /** Runs [action], recording its failure as one of [what]'s. */
    private suspend fun <T> recorded(what: () -> String, action: suspend () -> T): T = try {
        action()
    } catch (e: CancellationException) {
        throw e
    } catch (e: Exception) {
        val reason = (e as? RtcException)?.reason ?: e.message ?: e.toString()
        failedActions += FailedAction(what(), reason, bestEffort = currentCoroutineContext()[BestEffort] != null)
        throw e
    }

    /**
     * Makes [connection] again between the same ports, with its name and the properties a new connector
     * can reuse; fails when one of its ports belongs to a component the tree does not know.
     */
    suspend fun reconnect(connection: Connection) {
        val ports = connection.ports.map { end ->
            portRef((end.path ?: throw NotFoundException(end.fullName, "its component is unknown here: cannot connect it again")).toString())
        }
        val first = ports.first()
        act("connect again ${ports.joinToString(" to ")}", first.component, namesItself = true) { node ->
            node.port(first.name).connect(ports.drop(1).map { it.port() }, reusableProperties(connection.properties), connection.name)
        }
    }

    /**
     * Runs [action] on [selector]'s component, after [before]; when the component stopped answering
     * (re-created, moved) and another answers to the name now, runs [action] on that one, after [again].
     */
    suspend fun <T> withComponent(
        selector: String,
        before: (ComponentNode) -> Unit = {},
        again: (ComponentNode) -> Unit = {},
        action: suspend (ComponentNode) -> T,
    ): T {
        val node = component(selector)
        before(node)
        return try {
            action(node)
        } catch (e: UnreachableException) {
            val other = successor(selector, node) ?: throw e
            again(other)
            action(other)
        }
    }

    /**
     * The component that replaced [old], which stopped answering: the one bound at its path now, else
     * the one [selector] finds now; references and rules follow it.
     */
    private suspend fun successor(selector: String, old: ComponentNode): ComponentNode? =
        successorAt(old) ?: resolved.remove(selector).let { component(selector) }.takeUnless { it.isSameComponent(old) }?.also { follow(old, it) }

    /**
     * The component registered now where [old] was, if it is a different one: [old] was re-created, and
     * references and rules follow the new one. Only the binding's own context is read again.
     */
    suspend fun successorAt(old: ComponentNode): ComponentNode? =
        (registeredAt(old.path) as? ComponentNode)?.takeUnless { it.isSameComponent(old) }?.also { follow(old, it) }

    suspend fun create(ref: ManagerRef, type: String, name: String?): ComponentRef {
        val request = "create $type${name?.let { " as $it" } ?: ""}"
        var line = request
        val created = recorded({ line }) {
            val manager = manager(ref)
            line = "$request through ${manager.path}"
            log(line)
            try {
                manager.create(type, name)
            } catch (e: UnreachableException) {
                val again = restarted(manager, e) ?: throw e
                line = "$request through ${again.path}"
                log("$line (looked up again)")
                again.create(type, name)
            }
        }
        log("created ${created.path}")
        val reference = reference(created)
        currentCoroutineContext()[ActionJournal]?.record("$line: ${created.path}") { reference.exit() }
        return reference
    }

    /**
     * The manager now registered where [manager] was, if it is a new one and [failure] shows that the
     * request never reached the old one (refused, or the object gone), so sending it again cannot
     * create twice. A manager that died while it was creating is not asked again: the failure stands.
     */
    private suspend fun restarted(manager: ManagerNode, failure: UnreachableException): ManagerNode? {
        val cause = failure.cause
        if (cause !is org.omg.CORBA.TRANSIENT && cause !is org.omg.CORBA.OBJECT_NOT_EXIST) return null
        return (registeredAt(manager.path) as? ManagerNode)?.takeUnless { it === manager }
    }

    /** What is bound at [path] now, its parent listed again; null if nothing (reachable) is. */
    suspend fun registeredAt(path: RtcPath): Node? {
        val parent = path.parent ?: return null
        return try {
            tree.refresh(parent, depth = 0)
            tree.node(path)
        } catch (e: RtcException) {
            null
        }
    }

    suspend fun delete(ref: ManagerRef, instanceName: String) {
        var line = "delete $instanceName"
        recorded({ line }) {
            val manager = manager(ref)
            line = "delete $instanceName through ${manager.path}"
            log(line)
            manager.delete(instanceName)
        }
        resolved.keys.removeIf { it == instanceName || it.endsWith("/$instanceName.rtc") || it == "$instanceName.rtc" }
        currentCoroutineContext()[ActionJournal]?.record(line, null)
    }
}
