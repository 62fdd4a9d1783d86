package org.rtcoord.dsl

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.Recovered
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import java.util.concurrent.CopyOnWriteArrayList

/**
 * The rules on one component a script names, subscribed to whatever component answers to that name:
 * when the component dies (a zombie, or finalized), its path is looked at every poll period until a
 * different component is registered there, re-created by a rule or by hand, and the rules move to it.
 * So a rule keeps reacting to the component its script names, not to one CORBA object; the search ends
 * when the component recovers or the coordinator closes.
 */
internal class FollowedComponent(
    private val tree: RtcTree,
    private val engine: Engine,
    private val selector: String,
    private var node: ComponentNode,
    private val options: EventOptions,
    private val scope: CoroutineScope,
) : AutoCloseable {
    private val lock = Mutex()
    private val subscribers = mutableListOf<suspend (ComponentNode) -> Subscription>()
    private val active = CopyOnWriteArrayList<Subscription>()
    @Volatile private var search: Job? = null
    @Volatile private var closed = false

    /** Subscribes a rule with [subscribe], now to the current component and later to any that replaces it. */
    suspend fun add(subscribe: suspend (ComponentNode) -> Subscription): Unit = lock.withLock {
        // The rule first: the first registration attaches the observer, and the rule misses nothing after that.
        active += subscribe(node)
        if (subscribers.isEmpty()) watchLiveness(node)
        subscribers += subscribe
    }

    private suspend fun watchLiveness(target: ComponentNode) {
        active += tree.on(target, BecameZombie::class.java, options) { lost() }
        active += tree.on(target, ComponentFinalized::class.java, options) { lost() }
        active += tree.on(target, Recovered::class.java, options) { search?.cancel() }
    }

    private fun lost() {
        if (search?.isActive == true || closed) return
        search = scope.launch {
            val dead = node
            while (true) {
                delay(options.pollPeriod)
                val successor = engine.successor(selector, dead) ?: continue
                lock.withLock {
                    if (closed) return@launch
                    active.forEach(Subscription::cancel)
                    active.clear()
                    node = successor
                    subscribers.forEach { active += it(successor) }
                    watchLiveness(successor)
                }
                engine.log("$selector was re-created at ${successor.path}: its rules follow it")
                return@launch
            }
        }
    }

    /** Cancels the rules' subscriptions and any search. */
    override fun close() {
        closed = true
        search?.cancel()
        active.forEach(Subscription::cancel)
    }
}
