package org.rtcoord.dsl.internal

import java.nio.file.Path
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.coroutines.AbstractCoroutineContextElement
import kotlin.coroutines.CoroutineContext
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.flow.toList
import org.rtcoord.AmbiguousNameException
import org.rtcoord.ComponentNode
import org.rtcoord.Connection
import org.rtcoord.ManagerNode
import org.rtcoord.NodeFilters
import org.rtcoord.NodeFilters.and
import org.rtcoord.NodeKind
import org.rtcoord.NotFoundException
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.UnreachableException
import org.rtcoord.dsl.ComponentRef
import org.rtcoord.dsl.FailedAction
import org.rtcoord.dsl.ManagerRef
import org.rtcoord.dsl.portRef

/**
 * Performs a running coordinator's actions on the live tree, logging each, and resolves what they name through the
 * run's [identities]. It rides in the coroutine context of everything the run executes (handlers, timers, machines,
 * supervisors), which is how a script's references, plain selectors, find the run they act in: one plan can run several
 * times at once.
 */
internal class Engine(
    val tree: RtcTree,
    val identities: Identities,
    /** What the script's relative file names (profiles) are relative to. */
    val directory: Path,
    val log: (String) -> Unit,
    /** What watches the managers the run uses, if anything does (a check does not). */
    private val managers: ManagerWatch? = null,
) : AbstractCoroutineContextElement(Engine) {
    /** The one component [selector] names. */
    suspend fun component(selector: String): ComponentNode = identities.node(selector)

    /** A reference to [node], resolving to it. */
    fun reference(node: ComponentNode): ComponentRef =
        ComponentRef(node.path.toString()).also { identities.remember(node) }

    /** The manager [ref] names, watched from now on for its death and return. */
    suspend fun manager(ref: ManagerRef): ManagerNode = find(ref).also { managers?.watch(it) }

    /**
     * The manager [ref] names: by path, or by name on the first name server (in the run's order) that has one so named,
     * as `manager()` means the master manager of the first name server.
     */
    private suspend fun find(ref: ManagerRef): ManagerNode {
        if (ref.selector.startsWith("/")) return tree.manager(ref.selector)
        val found =
            tree.find(predicate = NodeFilters.kind(NodeKind.MANAGER) and NodeFilters.name(ref.selector)).toList()
        val first =
            tree.nameServers
                .map { server -> found.filter { it.path.nameServer == server.path.nameServer } }
                .firstOrNull { it.isNotEmpty() }
                .orEmpty()
        return when (first.size) {
            1 -> first.single() as ManagerNode
            0 ->
                throw NotFoundException(
                    ref.selector,
                    "no such manager on ${tree.nameServers.joinToString { it.address }}",
                )
            else -> throw AmbiguousNameException(ref.selector, first.map { it.path.toString() })
        }
    }

    /** Every action that failed so far, in order. */
    val failedActions: MutableList<FailedAction> = CopyOnWriteArrayList()

    /**
     * Runs [action] on [ref]'s component, logged as [what] (followed by the component's path, unless [what] names its
     * objects itself); once more after a fresh lookup if the component stopped answering.
     */
    suspend fun act(
        what: String,
        ref: ComponentRef,
        namesItself: Boolean = false,
        action: suspend (ComponentNode) -> Unit,
    ): Unit =
        actReversibly(what, ref, namesItself) {
            action(it)
            null
        }

    /**
     * [act], for an action that returns how to undo it: the handler's journal, if it runs in one, records the action
     * with its undo once it succeeded. A failure is recorded in [failedActions].
     */
    suspend fun actReversibly(
        what: String,
        ref: ComponentRef,
        namesItself: Boolean = false,
        action: suspend (ComponentNode) -> Undo?,
    ) {
        // Named by the script's selector until the component is found, so that a failed lookup still says what it was
        // for.
        var line = if (namesItself) what else "$what ${ref.selector}"
        fun describe(node: ComponentNode) = (if (namesItself) what else "$what ${node.path}").also { line = it }
        val undo =
            recorded({ line }) {
                withComponent(ref.selector, { log(describe(it)) }, { log("${describe(it)} (looked up again)") }, action)
            }
        currentCoroutineContext()[ActionJournal]?.record(line, undo)
    }

    /**
     * Runs [action], one on the whole system (a profile's restore), logged as [what] and journaled without an undo; its
     * failure is recorded as the others' are.
     */
    suspend fun <T> perform(what: String, action: suspend () -> T): T {
        log(what)
        return recorded({ what }, action).also { currentCoroutineContext()[ActionJournal]?.record(what, null) }
    }

    /** Runs [action], recording its failure as one of [what]'s. */
    private suspend fun <T> recorded(what: () -> String, action: suspend () -> T): T =
        catchFailure({
            ScriptCallSite.mark()
            action()
        }) { e ->
            val reason = (e as? RtcException)?.reason ?: e.message ?: e.toString()
            failedActions += FailedAction(what(), reason, bestEffort = currentCoroutineContext()[BestEffort] != null)
            throw e
        }

    /**
     * Makes [connection] again between the same ports, with its name and the properties a new connector can reuse;
     * fails when one of its ports belongs to a component the tree does not know.
     */
    suspend fun reconnect(connection: Connection) {
        val ports =
            connection.ports.map { end ->
                portRef(
                    (end.path
                            ?: throw NotFoundException(
                                end.fullName,
                                "its component is unknown here: cannot connect it again",
                            ))
                        .toString()
                )
            }
        val first = ports.first()
        act("connect again ${ports.joinToString(" to ")}", first.component, namesItself = true) { node ->
            node
                .port(first.name)
                .connect(ports.drop(1).map { it.port() }, reusableProperties(connection.properties), connection.name)
        }
    }

    /**
     * Runs [action] on [selector]'s component, after [before]; when the component stopped answering (re-created, moved)
     * and another answers to the name now, runs [action] on that one, after [again].
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
            val other = identities.successor(selector, node) ?: throw e
            again(other)
            action(other)
        }
    }

    suspend fun create(ref: ManagerRef, type: String, name: String?): ComponentRef {
        val request = "create $type${name?.let { " as $it" } ?: ""}"
        var line = request
        val created =
            recorded({ line }) {
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
        identities.adopt(created)
        val reference = ComponentRef(created.path.toString())
        currentCoroutineContext()[ActionJournal]?.record("$line: ${created.path}") { reference.exit() }
        return reference
    }

    /**
     * The manager now registered where [manager] was, if it is a new one and [failure] shows that the request never
     * reached the old one (refused, or the object gone), so sending it again cannot create twice. A manager that died
     * while it was creating is not asked again: the failure stands.
     */
    private suspend fun restarted(manager: ManagerNode, failure: UnreachableException): ManagerNode? {
        val cause = failure.cause
        if (cause !is org.omg.CORBA.TRANSIENT && cause !is org.omg.CORBA.OBJECT_NOT_EXIST) return null
        return (tree.registeredAt(manager.path) as? ManagerNode)?.takeUnless { it === manager }
    }

    suspend fun delete(ref: ManagerRef, instanceName: String) {
        var line = "delete $instanceName"
        recorded({ line }) {
            val manager = manager(ref)
            line = "delete $instanceName through ${manager.path}"
            log(line)
            manager.delete(instanceName)
        }
        identities.forget(instanceName)
        currentCoroutineContext()[ActionJournal]?.record(line, null)
    }

    companion object Key : CoroutineContext.Key<Engine> {
        /**
         * The engine of the run the caller executes in; notes where in its script the caller is (see [ScriptCallSite]).
         */
        suspend fun current(): Engine {
            val engine =
                currentCoroutineContext()[Engine]
                    ?: throw IllegalStateException(
                        "a component, port or manager acts only while a coordinator runs: in a rule's handler, a timer, a mode's action or an escalation handler"
                    )
            ScriptCallSite.mark()
            return engine
        }
    }
}
