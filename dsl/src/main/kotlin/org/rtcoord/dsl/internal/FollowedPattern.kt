package org.rtcoord.dsl.internal

import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.Subscription
import org.rtcoord.WatchMethodChanged

/**
 * A glob a running coordinator follows (`*`, `*_localise?.rtc`): every component whose name matches it, those there
 * when the first listener comes and those that appear later, created by anyone, until each exits. While anyone listens,
 * one subscription to the tree's root, which covers every name server and every component below them as they come: a
 * component the tree starts watching says so first (a [WatchMethodChanged]), which is when the pattern covers it. Each
 * listener has a [NodeListener] of its own per component, prepared before that component's first event reaches it, so
 * that one component's events never wait behind or replace another's.
 */
internal class FollowedPattern(val pattern: String, private val owner: Identities) : AutoCloseable {
    private class Listener(val types: Set<Class<out RtcEvent>>, val made: () -> NodeListener) {
        /** Its listener for each covered component; changed under the pattern's lock. */
        val perComponent = mutableListOf<Pair<ComponentNode, NodeListener>>()

        fun wants(event: RtcEvent) = types.any { it.isInstance(event) }

        fun of(node: ComponentNode): NodeListener? = perComponent.firstOrNull { it.first.isSameComponent(node) }?.second
    }

    private val lock = Mutex()
    private val listeners = CopyOnWriteArrayList<Listener>()
    /** The components it covers now; changed under [lock]. */
    private val covered = mutableListOf<ComponentNode>()
    private val matches = owner.globOf(pattern)
    @Volatile private var subscription: Subscription? = null
    @Volatile private var closed = false

    /**
     * What the subscription asks the tree for: what the plan listens to of this pattern, how each component is watched
     * (its arrival) and its exit.
     */
    private val types: Set<Class<out RtcEvent>> =
        setOf(WatchMethodChanged::class.java, ComponentFinalized::class.java) + (owner.watched[pattern] ?: emptySet())

    /** Whether it holds a subscription to the tree. */
    val subscribed: Boolean
        get() = subscription != null

    /** Hands the events of [types] from every component it covers, now or later, to a listener [made] for each. */
    suspend fun listen(types: Set<Class<out RtcEvent>>, made: () -> NodeListener): Subscription {
        check(types.all { wanted -> this.types.any { it.isAssignableFrom(wanted) } }) {
            "$pattern is not watched for ${types.map { it.simpleName }}"
        }
        val listener = Listener(types, made)
        lock.withLock {
            listeners += listener
            if (subscription == null && !closed) {
                subscription = owner.tree.on(owner.tree.node(RtcPath("/")), this.types, owner.options.queued(), ::take)
                // Those there already are covered without a word; their arrival events find them covered.
                owner
                    .matching(pattern)
                    .filter { node -> covered.none { it.isSameComponent(node) } }
                    .forEach { cover(it) }
            } else {
                covered.forEach { attach(listener, it) }
            }
        }
        return Subscription {
            listeners.remove(listener)
            owner.scope.launch { lock.withLock { if (listeners.isEmpty()) unsubscribe() } }
        }
    }

    /**
     * Takes one event from the tree: covers a matching component on its first event, hands the event on, and lets go of
     * a component that exited.
     */
    private suspend fun take(event: RtcEvent): Unit = lock.withLock {
        val node = event.source as? ComponentNode ?: return
        if (covered.none { it.isSameComponent(node) }) {
            if (!matches(node) || event is ComponentFinalized) return
            cover(node)
            owner.log("'$pattern' now covers ${node.path}")
        }
        for (listener in listeners) if (listener.wants(event)) listener.of(node)?.deliver(event)
        if (event is ComponentFinalized) {
            covered.removeAll { it.isSameComponent(node) }
            listeners.forEach { listener -> listener.perComponent.removeAll { it.first.isSameComponent(node) } }
            owner.log("${node.path} is gone: '$pattern' no longer covers it")
        }
    }

    private suspend fun cover(node: ComponentNode) {
        covered += node
        listeners.forEach { attach(it, node) }
    }

    private suspend fun attach(listener: Listener, node: ComponentNode) {
        val each = listener.made()
        try {
            each.prepare(node)
        } catch (e: RtcException) {
            // Gone as soon as it came: its events, if any come, still reach the listener.
            owner.log("'$pattern' covers ${node.path}, which could not be read: ${e.reason}")
        }
        listener.perComponent += node to each
    }

    private fun unsubscribe() {
        subscription?.cancel()
        subscription = null
        covered.clear()
    }

    /** Stops the subscription. */
    override fun close() {
        closed = true
        listeners.clear()
        subscription?.cancel()
        subscription = null
    }
}
