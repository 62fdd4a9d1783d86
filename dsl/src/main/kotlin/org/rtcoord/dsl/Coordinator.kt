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
import org.rtcoord.NotFoundException
import org.rtcoord.RtcEvent
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicInteger

/**
 * Runs a [Coordination] against a live system: subscribes its rules, starts its timers, mode machines
 * and supervisors, and runs their handlers, one structured-concurrency scope for all of it. A failing
 * handler is logged and counted and the coordinator keeps running; [close] cancels running handlers and
 * detaches every observer. Rules and transitions on a component the script names (not a pattern) follow
 * it when it is re-created, by a supervisor, a rule or by hand.
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
    private val watches = CopyOnWriteArrayList<Watch>()
    private val supervisors = CopyOnWriteArrayList<Supervisor>()
    private val searches = ConcurrentHashMap<String, SuccessorSearch>()
    private val failureCount = AtomicInteger()
    /** The network patterns of the machines that are subscribed. */
    private val networkWatched = ConcurrentHashMap.newKeySet<EventPattern<*>>()

    /** How rules, transitions and supervisors watch: the host's choice, else the script's. */
    private val watching: EventOptions get() = options ?: coordination.watching

    private val interpreters = coordination.machines.map { machine ->
        MachineInterpreter(machine, scope, coordination.engine, Configurator(coordination.engine, scope), log, ::failed, ::watchNetwork)
    }

    /** How many handler runs failed so far. */
    public val failures: Int get() = failureCount.get()

    /** Every action that failed so far, in order: those that stopped a handler and the best efforts. */
    public val failedActions: List<FailedAction> get() = coordination.engine.failedActions.toList()

    private val ruleActivities = coordination.rules.associateWith { RuleActivity(it.description) }

    /** What each rule has done, in declaration order. */
    public val rules: List<RuleActivity> = ruleActivities.values.toList()

    /** What each supervisor has done, in declaration order; empty until [start]. */
    public val supervision: List<SupervisorActivity> get() = supervisors.map { it.activity }

    /** The coordination's mode machines as they run, in declaration order. */
    public val machines: List<RunningMachine> = interpreters.map { it.running }

    /** The running machine named [name]. */
    public fun machine(name: String): RunningMachine = machines.firstOrNull { it.name == name }
        ?: throw IllegalArgumentException("no machine named '$name' (machines: ${machines.joinToString { it.name }.ifEmpty { "none" }})")

    /**
     * Resolves every rule's target and subscribes it, and starts the supervisors; fails (with nothing
     * left running) when a target does not exist or is ambiguous.
     */
    public suspend fun start() {
        coordination.engine.tree = tree
        coordination.engine.log = log
        coordination.engine.followed = ::follow
        coordination.nameServers.forEach(tree::addNameServer)
        try {
            coordination.rules.forEach { subscribe(it, targets(it.target)) }
            interpreters.forEach { watch(it) }
            coordination.supervisions.forEach { supervision ->
                supervisors += Supervisor(supervision, tree, coordination.engine, watching, scope, log) { escalated(supervision, it) }.also { it.start() }
            }
        } catch (e: Exception) {
            close()
            throw e
        }
        coordination.timers.forEach { timer ->
            scope.launch {
                delay(timer.delay)
                while (isActive) {
                    run("timer ${timer.description}") { Reaction(coordination.engine, null).handle(timer.action) }
                    delay(timer.period ?: break)
                }
            }
        }
        interpreters.forEach(MachineInterpreter::start)
    }

    /** Subscribes [machine]'s transitions, and what exists now of its networks. */
    private suspend fun watch(machine: MachineInterpreter) {
        watch(machine, machine.machine.eventPatterns) { targets(it.target) }
        watchNetwork(machine)
    }

    /**
     * Subscribes what [machine]'s networks name that exists now and is not watched yet: at the start, and
     * each time a network is done (a mode may create what its network names). Only the machine's own
     * coroutine calls it once the machine runs.
     */
    private suspend fun watchNetwork(machine: MachineInterpreter) {
        watch(machine, machine.networkWatch.patterns.filter { it !in networkWatched }) { pattern ->
            try {
                targets(pattern.target).also { networkWatched += pattern }
            } catch (e: NotFoundException) {
                emptyList()
            }
        }
    }

    /** Subscribes once per node and event type, however many of [patterns] watch for it. */
    private suspend fun watch(machine: MachineInterpreter, patterns: List<EventPattern<*>>, nodesOf: suspend (EventPattern<*>) -> List<Node>) {
        val groups = linkedMapOf<Pair<String, Class<*>>, Pair<Node, MutableList<EventPattern<*>>>>()
        for (pattern in patterns) {
            for (node in nodesOf(pattern)) groups.getOrPut(node.path.toString() to pattern.watched) { node to mutableListOf() }.second += pattern
        }
        for ((node, grouped) in groups.values) watch(machine, grouped, node)
    }

    private suspend fun watch(machine: MachineInterpreter, patterns: List<EventPattern<*>>, node: Node) {
        val subscription = patterns.first().watch(tree, node, watching, patterns) { machine.offer(it, patterns) }
        watches += Watch(node, subscription) { new -> watch(machine, patterns, new) }
        searchOnDeath(patterns.first().target, node)
    }

    private suspend fun <E : RtcEvent> subscribe(rule: Rule<E>, nodes: List<Node>) {
        for (node in nodes) {
            val subscription = rule.pattern.watch(tree, node, watching) { event -> rule.pattern.match(event)?.let { fire(rule, it) } }
            watches += Watch(node, subscription) { new -> subscribe(rule, listOf(new)) }
            searchOnDeath(rule.target, node)
        }
    }

    /**
     * Makes sure the death of [node], a component [target] names (not a pattern), starts a search for its
     * successor. After the rule's own subscription: the observer that attaches misses nothing for the rule.
     */
    private suspend fun searchOnDeath(target: Target, node: Node) {
        val named = when (target) {
            is Target.Component -> target.ref.takeUnless { it.isPattern }
            is Target.Port -> target.ref.component
            else -> null
        }
        if (named == null || node !is ComponentNode || searches.containsKey(named.selector)) return
        val search = SuccessorSearch(tree, coordination.engine, named.selector, node, watching, scope)
        if (searches.putIfAbsent(named.selector, search) == null) search.start()
    }

    /** Rules and transitions watching [old], a component since re-created as [new], watch [new] from now on. */
    private suspend fun follow(old: ComponentNode, new: ComponentNode) {
        for (watch in watches.filter { (it.node as? ComponentNode)?.isSameComponent(old) == true }) {
            // Whoever removes it moves it: a supervisor and a handler may follow the same component at once.
            if (!watches.remove(watch)) continue
            watch.subscription.cancel()
            watch.resubscribe(new)
        }
    }

    private suspend fun targets(target: Target): List<Node> = when (target) {
        is Target.Component -> coordination.engine.components(target.ref.selector)
        is Target.Port -> listOf(target.ref.component.node().also { it.port(target.ref.name) })
        is Target.Manager -> listOf(coordination.engine.manager(target.ref))
        is Target.Context -> listOf(tree.node(target.ref.path))
    }

    private suspend fun escalated(supervision: Supervision, escalation: Escalation) {
        for (handler in supervision.escalationHandlers) {
            run("escalation handler of ${escalation.supervisor}") { Reaction(coordination.engine, null).handle { handler(escalation) } }
        }
    }

    private suspend fun <E : RtcEvent> fire(rule: Rule<E>, event: E) {
        val reaction = Reaction(coordination.engine, event)
        if (!rule.guards.all { guard -> reaction.guard(event) }) return
        log("rule '${rule.description}' fired: ${describe(event)}")
        val activity = ruleActivities.getValue(rule)
        activity.fired(describe(event))
        run("rule '${rule.description}'", activity::failed) { reaction.handle { rule.handler(this, event) } }
    }

    private suspend fun run(what: String, failedAs: (String) -> Unit = {}, block: suspend () -> Unit) {
        try {
            block()
        } catch (e: CancellationException) {
            throw e
        } catch (e: Exception) {
            failed(what, e)
            failedAs(e.message ?: e.toString())
        }
    }

    private fun failed(what: String, e: Throwable) {
        failureCount.incrementAndGet()
        log("$what failed: ${e.message ?: e}")
    }

    /** Cancels running handlers and timers and detaches the rules' observers. Idempotent. */
    override fun close() {
        supervisors.forEach(Supervisor::close)
        searches.values.forEach(SuccessorSearch::close)
        searches.clear()
        watches.forEach { it.subscription.cancel() }
        watches.clear()
        scope.cancel()
    }

    /** A rule's or a machine's subscription to one of its target nodes, and how to make it again on another. */
    private class Watch(val node: Node, val subscription: Subscription, val resubscribe: suspend (Node) -> Unit)

    private companion object {
        fun describe(event: RtcEvent): String = "${event.javaClass.simpleName} at ${(event.source as? ComponentNode)?.path ?: event.path}"
    }
}
