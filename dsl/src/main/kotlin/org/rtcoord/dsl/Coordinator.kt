package org.rtcoord.dsl

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.Node
import org.rtcoord.RtcEvent
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicInteger

/**
 * Runs a [Coordination] against a live system: subscribes its rules, starts its timers, and runs their
 * handlers, one structured-concurrency scope for all of it. A failing handler is logged and counted and
 * the coordinator keeps running; [close] cancels running handlers and detaches every observer. Rules on
 * a component the script names (not a pattern) follow it when it dies and is re-created at its path.
 *
 * @param options how rules watch, overriding the script's own choice when given.
 * @param log receives one line per rule firing, action and failure.
 */
public class Coordinator(
    private val tree: RtcTree,
    private val coordination: Coordination,
    private val options: EventOptions? = null,
    private val log: (String) -> Unit = {},
) : AutoCloseable {
    private val scope = CoroutineScope(
        SupervisorJob() + CoroutineName("coordinator") + CoroutineExceptionHandler { _, e -> failed("timer", e) },
    )
    private val subscriptions = CopyOnWriteArrayList<Subscription>()
    private val followed = ConcurrentHashMap<String, FollowedComponent>()
    private val failureCount = AtomicInteger()

    /** How many handler runs failed so far. */
    public val failures: Int get() = failureCount.get()

    /**
     * Resolves every rule's target and subscribes it; fails (with nothing left running) when a target
     * does not exist or is ambiguous.
     */
    public suspend fun start() {
        coordination.engine.tree = tree
        coordination.engine.log = log
        coordination.nameServers.forEach(tree::addNameServer)
        try {
            coordination.rules.forEach { subscribe(it) }
        } catch (e: Exception) {
            close()
            throw e
        }
        coordination.timers.forEach { timer ->
            scope.launch {
                delay(timer.delay)
                while (isActive) {
                    run("timer ${timer.description}") { timer.action(Reaction(coordination.engine, null)) }
                    delay(timer.period ?: break)
                }
            }
        }
    }

    private suspend fun <E : RtcEvent> subscribe(rule: Rule<E>) {
        val watching = options ?: coordination.watching
        val named = when (val target = rule.target) {
            is Target.Component -> target.ref.takeUnless { it.isPattern }
            is Target.Port -> target.ref.component
            else -> null
        }
        for (node in targets(rule.target)) {
            val subscribe: suspend (Node) -> Subscription = { target -> tree.on(target, rule.type, watching) { event -> fire(rule, event) } }
            if (named == null || node !is ComponentNode) {
                subscriptions += subscribe(node)
                continue
            }
            // Rules on a named component follow it when it is re-created.
            followed.getOrPut(named.selector) { FollowedComponent(tree, coordination.engine, named.selector, node, watching, scope) }.add(subscribe)
        }
    }

    private suspend fun targets(target: Target): List<Node> = when (target) {
        is Target.Component -> coordination.engine.components(target.ref.selector)
        is Target.Port -> listOf(target.ref.component.node().also { it.port(target.ref.name) })
        is Target.Manager -> listOf(coordination.engine.manager(target.ref))
        is Target.Context -> listOf(tree.node(target.ref.path))
    }

    private suspend fun <E : RtcEvent> fire(rule: Rule<E>, event: E) {
        if (!rule.matches(event)) return
        val reaction = Reaction(coordination.engine, event)
        if (!rule.guards.all { guard -> reaction.guard(event) }) return
        log("rule '${rule.description}' fired: ${describe(event)}")
        run("rule '${rule.description}'") { rule.handler(reaction, event) }
    }

    private suspend fun run(what: String, block: suspend () -> Unit) {
        try {
            block()
        } catch (e: CancellationException) {
            throw e
        } catch (e: Exception) {
            failed(what, e)
        }
    }

    private fun failed(what: String, e: Throwable) {
        failureCount.incrementAndGet()
        log("$what failed: ${e.message ?: e}")
    }

    /** Cancels running handlers and timers and detaches the rules' observers. Idempotent. */
    override fun close() {
        followed.values.forEach(FollowedComponent::close)
        followed.clear()
        subscriptions.forEach(Subscription::cancel)
        subscriptions.clear()
        scope.cancel()
    }

    private companion object {
        fun describe(event: RtcEvent): String = "${event.javaClass.simpleName} at ${(event.source as? ComponentNode)?.path ?: event.path}"
    }
}
