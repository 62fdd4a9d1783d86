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
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import java.util.concurrent.CopyOnWriteArrayList

/**
 * Finds the component that replaces one a script names once it dies (a zombie, or finalized): its path
 * is read every poll period until a different component is registered there, re-created by a rule, a
 * supervisor or by hand; the engine then moves references, rules and transitions to it. So a rule keeps
 * reacting to the component its script names, not to one CORBA object. The search ends when the
 * component recovers or the coordinator closes.
 */
internal class SuccessorSearch(
    private val tree: RtcTree,
    private val engine: Engine,
    private val selector: String,
    @Volatile private var node: ComponentNode,
    private val options: EventOptions,
    private val scope: CoroutineScope,
) : AutoCloseable {
    private val lock = Mutex()
    private val liveness = CopyOnWriteArrayList<Subscription>()
    @Volatile private var search: Job? = null
    @Volatile private var closed = false

    /** Starts watching the component's liveness. */
    suspend fun start(): Unit = lock.withLock { watch(node) }

    private suspend fun watch(target: ComponentNode) {
        liveness += tree.on(target, BecameZombie::class.java, options) { lost() }
        liveness += tree.on(target, ComponentFinalized::class.java, options) { lost() }
        liveness += tree.on(target, Recovered::class.java, options) { search?.cancel() }
    }

    private fun lost() {
        if (search?.isActive == true || closed) return
        search = scope.launch {
            val dead = node
            while (true) {
                delay(options.pollPeriod)
                val successor = followedAlready(dead) ?: engine.successorAt(dead) ?: continue
                lock.withLock {
                    if (closed) return@launch
                    liveness.forEach(Subscription::cancel)
                    liveness.clear()
                    node = successor
                    watch(successor)
                }
                engine.log("$selector was re-created at ${successor.path}: its rules follow it")
                return@launch
            }
        }
    }

    /** The successor a supervisor or an action found and the references follow already, if any. */
    private suspend fun followedAlready(dead: ComponentNode): ComponentNode? = try {
        engine.component(selector).takeUnless { it.isSameComponent(dead) }
    } catch (e: RtcException) {
        null
    }

    /** Stops watching and searching. */
    override fun close() {
        closed = true
        search?.cancel()
        liveness.forEach(Subscription::cancel)
    }
}
