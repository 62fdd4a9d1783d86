@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl.internal

import java.util.concurrent.ConcurrentHashMap
import kotlinx.coroutines.CoroutineScope
import org.rtcoord.AmbiguousNameException
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.Node
import org.rtcoord.NodeFilters
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import org.rtcoord.internal.componentsFound

/**
 * The one owner of "which component is this" in a running coordinator: resolves what a script names (a path, a name
 * found on any name server, or a pattern that matches one component) and follows each name to the component that
 * replaces it when it is re-created, whoever re-creates it (a supervisor, a handler, someone by hand); a pattern
 * listened to covers every component that matches it, including those that appear later (see [FollowedPattern]). Those
 * who need to know what a name refers to now (a supervisor) ask it and keep no copy. Each name or pattern listened to
 * has one subscription to the tree, shared by every rule, machine and supervisor that listens to it (see
 * [FollowedComponent]).
 *
 * @param watched the events the plan listens to, by name: a name's subscription asks the tree for these alone, so a
 *   component only rules on states watch is read for its states alone.
 */
internal class Identities(
    val tree: RtcTree,
    val options: EventOptions,
    val scope: CoroutineScope,
    val log: (String) -> Unit,
    val watched: Map<String, Set<Class<out RtcEvent>>>,
) : AutoCloseable {
    private val names = ConcurrentHashMap<String, FollowedComponent>()
    private val patterns = ConcurrentHashMap<String, FollowedPattern>()

    /** How many subscriptions to the tree the followed names and patterns hold now. */
    val subscriptions: Int
        get() = names.values.count { it.subscribed } + patterns.values.count { it.subscribed }

    /** The one component [selector] names, as resolved before or resolved now. */
    suspend fun node(selector: String): ComponentNode = followed(selector).node

    /** Every component [selector] names now: one for a name or path, those a pattern matches now for a pattern. */
    suspend fun nodes(selector: String): List<ComponentNode> =
        if (isPattern(selector)) matching(selector) else listOf(node(selector))

    /**
     * Calls [listener] with every event of [types] from the component [selector] names, in order, and then from each
     * component that replaces it. [prepare] reads what the listener follows of a component before that component's
     * first event reaches it.
     */
    suspend fun listen(
        selector: String,
        types: Set<Class<out RtcEvent>>,
        prepare: suspend (ComponentNode) -> Unit = {},
        listener: suspend (RtcEvent) -> Unit,
    ): Subscription = followed(selector).listen(types, prepare, listener)

    /**
     * Hands the events of [types] from what [selector] names to a listener [made] for each component: the one a name
     * refers to, followed through re-creation; every one a pattern covers, now and later.
     */
    suspend fun listen(selector: String, types: Set<Class<out RtcEvent>>, made: () -> NodeListener): Subscription {
        if (isPattern(selector))
            return patterns.computeIfAbsent(selector) { FollowedPattern(it, this) }.listen(types, made)
        val listener = made()
        return listen(selector, types, listener::prepare, listener::deliver)
    }

    /** Remembers [node] as what its path names, so that a reference made from it resolves to it. */
    fun remember(node: ComponentNode) {
        names.computeIfAbsent(node.path.toString()) { FollowedComponent(it, node, this) }
    }

    /**
     * Remembers [node], created just now, as what its path names: a component that held the path before (it exited, and
     * the name was given again) is replaced by it, for every name that resolved to that one.
     */
    suspend fun adopt(node: ComponentNode) {
        val previous = names[node.path.toString()]?.node
        if (previous == null || previous.isSameComponent(node)) remember(node) else follow(previous, node)
    }

    /** Every name that resolved to [old], a component since re-created as [new], names [new] from now on. */
    suspend fun follow(old: ComponentNode, new: ComponentNode) {
        for (name in names.values) if (name.node.isSameComponent(old)) name.moveTo(new)
    }

    /**
     * The component that replaced [old], which stopped answering, and that [selector] names from now on: the one bound
     * at [old]'s path now, else the one [selector] finds now; null if neither is another.
     */
    suspend fun successor(selector: String, old: ComponentNode): ComponentNode? {
        successorAt(old)?.let {
            return it
        }
        val again =
            try {
                resolve(selector)
            } catch (e: RtcException) {
                return null
            }
        return again.takeUnless { it.isSameComponent(old) }?.also { follow(old, it) }
    }

    /**
     * The component registered now where [old] was, if it is another one: [old] was re-created, and its names follow
     * it.
     */
    suspend fun successorAt(old: ComponentNode): ComponentNode? =
        (tree.registeredAt(old.path) as? ComponentNode)
            ?.takeUnless { it.isSameComponent(old) }
            ?.also { follow(old, it) }

    /**
     * Forgets the names of component [instanceName], deleted, so that they resolve afresh when used again; a name
     * something listens to stays, and follows the component when it is created again.
     */
    fun forget(instanceName: String) {
        names.entries.removeIf { (name, followed) ->
            val gone =
                (name == instanceName || name.endsWith("/$instanceName.rtc") || name == "$instanceName.rtc") &&
                    !followed.subscribed
            gone.also { if (it) followed.close() }
        }
    }

    /** Stops every subscription and search. */
    override fun close() {
        (names.values + patterns.values).forEach(AutoCloseable::close)
        names.clear()
        patterns.clear()
    }

    /**
     * What [selector] (not a pattern) names, resolved now if it never was: its [FollowedComponent.node] is the
     * component it refers to from then on.
     */
    suspend fun followed(selector: String): FollowedComponent {
        names[selector]?.let {
            return it
        }
        val node = resolve(selector)
        return names.computeIfAbsent(selector) { FollowedComponent(it, node, this) }
    }

    private suspend fun resolve(selector: String): ComponentNode =
        when {
            selector.startsWith("/") || selector.startsWith("corbaloc:") -> tree.component(selector)
            isPattern(selector) ->
                matching(selector).singleOrNull()
                    ?: throw AmbiguousNameException(selector, matching(selector).map { it.path.toString() })
            else -> tree.componentNamed(selector)
        }

    /** The components [pattern] matches now, each once however many paths reach it. */
    suspend fun matching(pattern: String): List<ComponentNode> {
        val glob = globOf(pattern)
        return componentsFound(listOf(tree.root)) { glob(it) }
    }

    /**
     * Whether a node matches [pattern]: its name the glob (a glob without a kind, `laser*`, is of components,
     * `laser*.rtc`), and for a typed selector its type, as its profile says it.
     */
    fun globOf(pattern: String): suspend (Node) -> Boolean {
        val glob = Selectors.name(pattern)
        val named = NodeFilters.name(if ('.' in glob) glob else "$glob.rtc")
        val type = Selectors.type(pattern) ?: return named
        return { node -> named(node) && (node as? ComponentNode)?.let { typeOf(it) } == type }
    }

    /** [node]'s type name; null when it cannot be read (gone as it came). */
    private suspend fun typeOf(node: ComponentNode): String? =
        try {
            node.snapshot().typeName
        } catch (e: RtcException) {
            null
        }

    private companion object {
        fun isPattern(selector: String) = Selectors.isPattern(selector)
    }
}

/** What is bound at [path] now, its parent listed again; null if nothing (reachable) is. */
internal suspend fun RtcTree.registeredAt(path: RtcPath): Node? {
    val parent = path.parent ?: return null
    return try {
        refresh(parent, depth = 0)
        node(path)
    } catch (e: RtcException) {
        null
    }
}
