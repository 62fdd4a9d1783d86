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
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicInteger

/**
 * Runs a [Coordination] against a live system: subscribes its rules, starts its timers and mode
 * machines, and runs their handlers, one structured-concurrency scope for all of it. A failing handler
 * is logged and counted and the coordinator keeps running; [close] cancels running handlers and
 * detaches every observer.
 *
 * @param options how rules watch, overriding the script's own choice when given.
 * @param log receives one line per rule firing, action, mode transition and failure.
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
    private val failureCount = AtomicInteger()

    private val interpreters = coordination.machines.map { machine ->
        MachineInterpreter(machine, scope, coordination.engine, Configurator(coordination.engine, scope), log, ::failed)
    }

    /** How many handler runs failed so far. */
    public val failures: Int get() = failureCount.get()

    /** The coordination's mode machines as they run, in declaration order. */
    public val machines: List<RunningMachine> = interpreters.map { it.running }

    /** The running machine named [name]. */
    public fun machine(name: String): RunningMachine = machines.firstOrNull { it.name == name }
        ?: throw IllegalArgumentException("no machine named '$name' (machines: ${machines.joinToString { it.name }.ifEmpty { "none" }})")

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
            interpreters.forEach { watch(it) }
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
        interpreters.forEach(MachineInterpreter::start)
    }

    /** Subscribes once per node and event type, however many of [machine]'s transitions watch for it. */
    private suspend fun watch(machine: MachineInterpreter) {
        val watching = options ?: coordination.watching
        val groups = linkedMapOf<Pair<String, Class<*>>, Pair<Node, MutableList<EventPattern<*>>>>()
        for (pattern in machine.machine.eventPatterns) {
            for (node in targets(pattern.target)) groups.getOrPut(node.path.toString() to pattern.type) { node to mutableListOf() }.second += pattern
        }
        for ((node, patterns) in groups.values) subscriptions += patterns.first().watch(tree, node, watching) { machine.offer(it, patterns) }
    }

    private suspend fun <E : RtcEvent> subscribe(rule: Rule<E>) {
        val watching = options ?: coordination.watching
        for (node in targets(rule.target)) {
            subscriptions += tree.on(node, rule.type, watching) { event -> fire(rule, event) }
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
        subscriptions.forEach(Subscription::cancel)
        subscriptions.clear()
        scope.cancel()
    }

    private companion object {
        fun describe(event: RtcEvent): String = "${event.javaClass.simpleName} at ${(event.source as? ComponentNode)?.path ?: event.path}"
    }
}
