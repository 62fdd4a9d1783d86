package org.rtcoord.dsl.internal

import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.Subscription

/**
 * One name a running coordinator follows: the component it resolves to now ([node]); while anyone listens, one
 * subscription to the tree for it, whose events go to every listener in the order they happened. When the component
 * dies (a zombie, or finalized) its path is read every poll period until another component is registered there; when it
 * is re-created, found so or told to the [owner] by whoever re-created it, the subscription moves to the new component,
 * each listener having read it first.
 */
internal class FollowedComponent(val selector: String, initial: ComponentNode, private val owner: Identities) :
    AutoCloseable {
    /** The component the name refers to now. */
    @Volatile
    var node: ComponentNode = initial
        private set

    private class Listener(
        val types: Set<Class<out RtcEvent>>,
        val prepare: suspend (ComponentNode) -> Unit,
        val deliver: suspend (RtcEvent) -> Unit,
    ) {
        fun wants(event: RtcEvent) = types.any { it.isInstance(event) }
    }

    private val lock = Mutex()
    private val listeners = CopyOnWriteArrayList<Listener>()
    @Volatile private var subscription: Subscription? = null
    @Volatile private var search: Job? = null
    @Volatile private var closed = false

    /** What the subscription asks the tree for: what the plan listens to of this name, and the component's liveness. */
    private val types: Set<Class<out RtcEvent>> = LIVENESS + (owner.watched[selector] ?: emptySet())

    /** Whether it holds a subscription to the tree. */
    val subscribed: Boolean
        get() = subscription != null

    /**
     * Hands [deliver] the events of [types] from the component, and from those that replace it, once [prepare] read
     * each.
     */
    suspend fun listen(
        types: Set<Class<out RtcEvent>>,
        prepare: suspend (ComponentNode) -> Unit,
        deliver: suspend (RtcEvent) -> Unit,
    ): Subscription {
        check(types.all { wanted -> this.types.any { it.isAssignableFrom(wanted) } }) {
            "$selector is not watched for ${types.map { it.simpleName }}"
        }
        val listener = Listener(types, prepare, deliver)
        lock.withLock {
            listener.prepare(node)
            listeners += listener
            if (subscription == null && !closed) subscription = subscribe(node)
        }
        return Subscription {
            listeners.remove(listener)
            if (listeners.isEmpty()) owner.scope.launch { lock.withLock { if (listeners.isEmpty()) unsubscribe() } }
        }
    }

    /** Follows [new], which replaced the component followed so far. */
    suspend fun moveTo(new: ComponentNode): Unit = lock.withLock {
        if (closed || node.isSameComponent(new)) return
        // A search under way ends by itself once it sees the name moved.
        node = new
        if (listeners.isEmpty()) return
        listeners.forEach { it.prepare(new) }
        val old = subscription
        subscription = subscribe(new)
        old?.cancel()
        owner.log("$selector was re-created at ${new.path}: its rules follow it")
    }

    private suspend fun subscribe(target: ComponentNode): Subscription =
        owner.tree.on(target, types, owner.options.queued()) { event ->
            when (event) {
                is BecameZombie,
                is ComponentFinalized -> searchSuccessor(target)
                is Recovered -> search?.cancel()
                else -> Unit
            }
            for (listener in listeners) if (listener.wants(event)) listener.deliver(event)
        }

    /** Reads [dead]'s path every poll period until another component is registered there, then follows it. */
    private fun searchSuccessor(dead: ComponentNode) {
        if (search?.isActive == true || closed) return
        search =
            owner.scope.launch {
                while (node.isSameComponent(dead)) {
                    delay(owner.options.pollPeriod)
                    owner.successorAt(dead)
                }
            }
    }

    private fun unsubscribe() {
        subscription?.cancel()
        subscription = null
    }

    /** Stops the subscription and the search. */
    override fun close() {
        closed = true
        search?.cancel()
        listeners.clear()
        unsubscribe()
    }

    private companion object {
        val LIVENESS: Set<Class<out RtcEvent>> =
            setOf(BecameZombie::class.java, ComponentFinalized::class.java, Recovered::class.java)
    }
}
