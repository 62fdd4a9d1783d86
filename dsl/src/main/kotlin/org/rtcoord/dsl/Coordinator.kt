@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.isActive
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import org.rtcoord.ClosedException
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.Node
import org.rtcoord.NotFoundException
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.Subscription
import org.rtcoord.dsl.internal.ActionJournal
import org.rtcoord.dsl.internal.Configurator
import org.rtcoord.dsl.internal.DataRuleRun
import org.rtcoord.dsl.internal.Engine
import org.rtcoord.dsl.internal.HandlerQueue
import org.rtcoord.dsl.internal.Identities
import org.rtcoord.dsl.internal.MachineInterpreter
import org.rtcoord.dsl.internal.ManagerWatch
import org.rtcoord.dsl.internal.NetworkWatch
import org.rtcoord.dsl.internal.NodeListener
import org.rtcoord.dsl.internal.ScriptCallSite
import org.rtcoord.dsl.internal.Supervisor
import org.rtcoord.dsl.internal.catchFailure
import org.rtcoord.dsl.internal.plan
import org.rtcoord.dsl.internal.queued
import org.rtcoord.internal.treeScope
import org.rtcoord.internal.treeTime

/**
 * Runs a [Coordination]'s plan against a live system: subscribes its rules, starts its timers, mode machines and
 * supervisors, and runs their handlers, one structured-concurrency scope for all of it. A failing handler is logged and
 * counted and the coordinator keeps running; [close] cancels running handlers and detaches every observer. What the
 * script names (not a pattern) is followed when it is re-created, by a supervisor, a rule or by hand, with one
 * subscription per component however many rules, transitions and supervisors watch it. The plan is taken when the
 * coordinator is made: several coordinators may run one coordination, one after another or at once.
 *
 * @param options how rules watch, overriding the script's own choice when given.
 * @param log receives one line per rule firing, action, mode transition and failure.
 */
public class Coordinator(
    private val tree: RtcTree,
    coordination: Coordination,
    options: EventOptions? = null,
    private val log: (String) -> Unit = {},
) : AutoCloseable {
    private val plan = coordination.plan()

    /** The coordination's [name][Coordination.name]: the script's file name, or the name given in code. */
    public val name: String = coordination.name

    /** How rules, transitions and supervisors watch: the host's choice, else the script's. */
    private val watching: EventOptions = options ?: plan.watching

    /** A child of the tree's: the coordinator runs on the tree's threads, which end only once it has. */
    private val job = SupervisorJob(tree.treeScope().coroutineContext.job)
    private val context = tree.treeScope().coroutineContext + job
    private val identities =
        Identities(tree, watching, CoroutineScope(context + CoroutineName("coordinator names")), log, watchedByName())
    private val managers = ManagerWatch(tree, watching, log)
    private val engine = Engine(tree, identities, plan.directory, log, managers)
    private val scope =
        CoroutineScope(
            context + CoroutineName("coordinator") + engine + CoroutineExceptionHandler { _, e -> failed("timer", e) }
        )
    private val interpreters =
        plan.machines.map {
            MachineInterpreter(
                it,
                scope,
                engine,
                Configurator(engine, scope),
                log,
                ::failed,
                ::watchNetwork,
                time = tree.treeTime(),
            )
        }
    /** The listeners of followed names, and the subscriptions to nodes that are not followed. */
    private val listeners = CopyOnWriteArrayList<Subscription>()
    private val subscriptions = CopyOnWriteArrayList<Subscription>()
    /** The running supervisors, in declaration order; empty until [start]. */
    internal val supervisors = CopyOnWriteArrayList<Supervisor>()
    private val dataRuns = CopyOnWriteArrayList<DataRuleRun>()
    private val failureCount = MutableStateFlow(0)
    private val failureList = CopyOnWriteArrayList<HandlerFailure>()

    /** How many handler runs failed so far: the size of [handlerFailures]. */
    public val failures: Int
        get() = failureCount.value

    /**
     * Every handler run that failed so far, in order, each with its subject and the line of the script it failed at.
     */
    public val handlerFailures: List<HandlerFailure>
        get() = failureList.toList()

    /** [failures] as it changes, for those who wait for the first: `failureCounts.first { it > 0 }`. */
    public val failureCounts: StateFlow<Int> = failureCount.asStateFlow()

    /** Every action that failed so far, in order: those that stopped a handler and the best efforts. */
    public val failedActions: List<FailedAction>
        get() = engine.failedActions.toList()

    private val ruleActivities = plan.rules.associateWith { RuleActivity(it.description) }

    /** What each rule has done, in declaration order. */
    public val rules: List<RuleActivity> = ruleActivities.values.toList()

    /**
     * What each supervisor has done, in declaration order: there from the coordinator's making, so that a view can
     * follow it before [start]; a supervisor's [status][SupervisorActivity.status] changes once it runs.
     */
    public val supervision: List<SupervisorActivity> =
        plan.supervisions.map { SupervisorActivity(it.name, it.strategy.name) }

    /** The coordination's mode machines as they run, in declaration order. */
    public val machines: List<RunningMachine> = interpreters.map { it.running }

    /** Whether every coroutine of the coordinator has ended, once [close]d: nothing it ran can act any more. */
    internal val ended: Boolean
        get() = job.isCompleted

    /**
     * How many subscriptions to the tree the coordinator holds now: one per followed component, one per other node
     * watched.
     */
    internal val treeSubscriptions: Int
        get() = identities.subscriptions + subscriptions.size

    /** The running machine named [name]. */
    public fun machine(name: String): RunningMachine =
        machines.firstOrNull { it.name == name }
            ?: throw IllegalArgumentException(
                "no machine named '$name' (machines: ${machines.joinToString { it.name }.ifEmpty { "none" }})"
            )

    /**
     * Resolves every rule's target and subscribes it, and starts the supervisors; fails (with nothing left running)
     * when a target does not exist or is ambiguous, and with a [ClosedException] once the coordinator is closed: a
     * closed coordinator does not start again (make a new one).
     */
    public suspend fun start() {
        // Not kotlinx's JobCancellationException from the first suspension in the cancelled scope.
        if (!job.isActive) throw ClosedException("coordinator $name")
        plan.nameServers.forEach(tree::addNameServer)
        try {
            managers.start()
            plan.rules.forEach { subscribe(it) }
            withContext(engine) {
                plan.dataRules.forEach { rule ->
                    DataRuleRun(rule, engine, scope) { what, handler ->
                            react("rule $what", Reaction(engine, null), handler = handler)
                        }
                        .also { dataRuns += it }
                        .start()
                }
            }
            interpreters.forEach { machine ->
                watch(machine, machine.machine.eventPatterns)
                watchNetwork(machine)
            }
            plan.supervisions.zip(supervision).forEach { (supervision, activity) ->
                supervisors +=
                    Supervisor(supervision, activity, engine, scope, log, tree.treeTime()) {
                            escalated(supervision, it)
                        }
                        .also { it.start() }
            }
            // Last: watching a manager watches the components below it, and the tree names each component by the path
            // it
            // was first watched at; the rules' names (naming contexts) come first.
            plan.managers.forEach { watchManager(it) }
        } catch (e: Exception) {
            close()
            throw e
        }
        plan.timers.forEach { timer ->
            scope.launch {
                delay(timer.delay)
                while (isActive) {
                    react(timer.subject, Reaction(engine, null), handler = timer.action)
                    delay(timer.period ?: break)
                }
            }
        }
        interpreters.forEach(MachineInterpreter::start)
    }

    /** Watches manager [selector] for its death and return; one not found now is watched once a handler uses it. */
    private suspend fun watchManager(selector: String) {
        try {
            engine.manager(ManagerRef(selector))
        } catch (e: RtcException) {
            log("manager $selector: ${e.reason}; watched once the script uses it")
        }
    }

    /**
     * The events the plan watches of each name it follows, so that each name's one subscription asks the tree for all
     * of them and no more; a supervised component is watched for everything.
     */
    private fun watchedByName(): Map<String, Set<Class<out RtcEvent>>> {
        val patterns =
            plan.rules.map { it.pattern } + plan.machines.flatMap { it.eventPatterns + NetworkWatch(it).patterns }
        val named =
            patterns.mapNotNull { pattern -> pattern.target.followedName?.let { it to pattern.watched } } +
                plan.supervisions.flatMap { supervision ->
                    supervision.children.map { it.selector to RtcEvent::class.java }
                }
        return named.groupBy({ it.first }, { it.second }).mapValues { it.value.toSet() }
    }

    private suspend fun <E : RtcEvent> subscribe(rule: Rule<E>) {
        val matcher = rule.pattern.matcher()
        listen(rule.target, setOf(rule.pattern.watched)) {
            val handler = HandlerQueue(scope, watching.overlap) { event: E -> fire(rule, event) }
            object : NodeListener {
                override suspend fun prepare(node: Node) {
                    matcher.prepare(node)?.let(handler::offer)
                }

                override suspend fun deliver(event: RtcEvent) {
                    matcher.match(event)?.let(handler::offer)
                }
            }
        }
    }

    /** Subscribes [patterns], transitions or network watches of [machine], one listener per target. */
    private suspend fun watch(machine: MachineInterpreter, patterns: List<EventPattern<*>>) {
        for (grouped in patterns.groupBy { it.target.key }.values) {
            listen(grouped.first().target, grouped.map { it.watched }.toSet()) {
                object : NodeListener {
                    override suspend fun prepare(node: Node) = machine.prepare(grouped, node)

                    override suspend fun deliver(event: RtcEvent) = machine.offer(event, grouped)
                }
            }
        }
    }

    /**
     * Subscribes what [machine]'s networks name that exists now and is not watched yet: at the start, and each time a
     * network is done (a mode may create what its network names). Only the machine's own coroutine calls it once the
     * machine runs.
     */
    private suspend fun watchNetwork(machine: MachineInterpreter) {
        for (grouped in machine.networkWatch.unwatched().groupBy { it.target.key }.values) {
            try {
                watch(machine, grouped)
                machine.networkWatch.watching(grouped)
            } catch (e: NotFoundException) {
                // Not there yet: watched once a network that makes it is done.
            } catch (e: RtcException) {
                // Its name server restarting, say: the machine goes on, and says what it does not watch.
                log(
                    "machine ${machine.machine.name}: cannot watch ${grouped.first().target.key} (${e.message}): " +
                        "tried again when a network is done"
                )
            }
        }
    }

    /**
     * Hands the events of [types] from what [target] names to a listener [made] for each node: a component the script
     * names is followed across re-creation, and a pattern covers every match as they come and go, each on its one
     * subscription; a manager or naming context is watched by a subscription of its own, which covers the components
     * below it as they come and go.
     */
    private suspend fun listen(target: Target, types: Set<Class<out RtcEvent>>, made: () -> NodeListener) {
        when (target) {
            is Target.Component -> listeners += identities.listen(target.ref.selector, types, made)
            is Target.Port -> {
                identities.node(target.ref.component.selector).port(target.ref.name)
                listeners += identities.listen(target.ref.component.selector, types, made)
            }
            is Target.Manager -> watchDirectory(engine.manager(target.ref), types, made())
            is Target.Context -> watchDirectory(tree.node(target.ref.path), types, made())
            Target.Logs -> watchDirectory(tree.root, types, made())
        }
    }

    private suspend fun watchDirectory(directory: Node, types: Set<Class<out RtcEvent>>, listener: NodeListener) {
        listener.prepare(directory)
        subscriptions += tree.on(directory, types, watching.queued()) { listener.deliver(it) }
    }

    private suspend fun escalated(supervision: Supervision, escalation: Escalation) {
        for (handler in supervision.escalationHandlers) {
            react("escalation handler of ${escalation.supervisor}", Reaction(engine, null)) { handler(escalation) }
        }
    }

    /**
     * Runs [rule]'s handler on [event] if every guard holds. Called in [scope] (its [HandlerQueue]'s coroutine), whose
     * context carries the run's engine: no context to switch to, as often as records come.
     */
    private suspend fun <E : RtcEvent> fire(rule: Rule<E>, event: E) {
        val reaction = Reaction(engine, event)
        if (!rule.guards.all { guard -> reaction.guard(event) }) return
        val described = describe(event)
        log("rule '${rule.description}' fired: $described")
        val activity = ruleActivities.getValue(rule)
        activity.fired(described)
        try {
            react("rule '${rule.description}'", reaction, activity::failed) { rule.handler(this, event) }
        } finally {
            activity.returned()
        }
    }

    /**
     * Runs [handler] as [reaction]'s, its actions journaled and its script frames tracked in one switch of context; a
     * failure is counted and logged as [what]'s.
     */
    private suspend fun react(
        what: String,
        reaction: Reaction,
        failedAs: (String) -> Unit = {},
        handler: suspend Reaction.() -> Unit,
    ) {
        val journal = ActionJournal()
        catchFailure({ ScriptCallSite.tracking(journal) { reaction.handle(journal, handler) } }) { e ->
            failed(what, e)
            failedAs(e.message ?: e.toString())
        }
    }

    /**
     * Lists the failure, logs it, then counts it: whoever sees the line finds it in the list, and whoever sees the
     * count both.
     */
    private fun failed(what: String, e: Throwable) {
        val failure = HandlerFailure.of(what, e)
        failureList += failure
        log(failure.toString())
        failureCount.update { it + 1 }
    }

    /**
     * Runs the script's `onStop` actions, each within 10 s (one that takes longer is cut short and logged), then
     * [close]s and waits (up to 10 s) for what it cancelled to end: what a host calls to end a run the script is told
     * of. Once it returns, each machine's mode is the last it recorded, not one it was leaving.
     */
    public suspend fun stop() {
        withContext(engine) {
            for (action in plan.stopActions) {
                withTimeoutOrNull(STOP_LIMIT) { react("on stop", Reaction(engine, null), handler = action) }
                    ?: log("on stop did not finish within $STOP_LIMIT: cut short")
            }
        }
        close()
        // Not from the coordinator's own coroutines (a handler stopping it), which would wait for themselves.
        if (currentCoroutineContext()[Engine] == null) withTimeoutOrNull(STOP_LIMIT) { job.join() }
    }

    /**
     * Cancels running handlers and timers and detaches the rules' observers, without the script's `onStop` actions
     * ([stop] runs them). Idempotent.
     */
    override fun close() {
        supervisors.forEach(Supervisor::close)
        dataRuns.forEach(DataRuleRun::stop)
        dataRuns.clear()
        (listeners + subscriptions).forEach(Subscription::cancel)
        listeners.clear()
        subscriptions.clear()
        managers.close()
        identities.close()
        job.cancel()
    }

    private companion object {
        /** How long each `onStop` action may take: a stop must end, even with a handler that hangs. */
        val STOP_LIMIT = 10.seconds

        fun describe(event: RtcEvent): String =
            "${event.javaClass.simpleName} at ${(event.source as? ComponentNode)?.path ?: event.path}"
    }
}
