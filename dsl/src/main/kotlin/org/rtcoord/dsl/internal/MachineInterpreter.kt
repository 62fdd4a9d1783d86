package org.rtcoord.dsl.internal

import java.time.Instant
import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import org.rtcoord.Node
import org.rtcoord.RtcEvent
import org.rtcoord.dsl.EventPattern
import org.rtcoord.dsl.Link
import org.rtcoord.dsl.Mode
import org.rtcoord.dsl.ModeMachine
import org.rtcoord.dsl.ModeTransition
import org.rtcoord.dsl.Network
import org.rtcoord.dsl.NetworkOutcome
import org.rtcoord.dsl.Reaction
import org.rtcoord.dsl.RunningMachine
import org.rtcoord.dsl.Transition
import org.rtcoord.dsl.Trigger
import org.slf4j.LoggerFactory

/**
 * Runs a [ModeMachine], UML/SCXML style. Inputs (watched events, reconfiguration outcomes, timeouts) queue without
 * limit and are handled one at a time, each to completion: the first transition of the innermost active mode whose
 * trigger matches and whose guards hold is taken (outer modes' transitions apply when no inner one does); exits run
 * innermost first up to the least common ancestor of source and target, then the transition's action, then entries
 * outermost first down to the target and its initial modes. An input no transition takes is counted and logged at debug
 * level, never dropped unseen.
 *
 * Entering a mode that declares a network brings the system to the merged network of the active modes through the
 * [Configurator], in the background, and queues `done` or `failed`. Leaving or entering a mode that declares one
 * cancels a reconfiguration still under way: its outcome never arrives. A mode's `after` timers start once its entry
 * actions ran and stop when it is left.
 *
 * Once a network is done, it is watched while its modes stay active (see [NetworkWatch]): the first breach is logged
 * and raised as `networkBroken`, later ones logged only, until the next network is done.
 *
 * Only the machine's own coroutine touches its state; others only queue inputs.
 */
internal class MachineInterpreter(
    val machine: ModeMachine,
    private val scope: CoroutineScope,
    private val engine: Engine,
    private val configurator: Configurator,
    private val log: (String) -> Unit,
    private val failed: (String, Throwable) -> Unit,
    /** Watches the network components that exist now and were not watched yet. */
    private val watchNetwork: suspend (MachineInterpreter) -> Unit = {},
    private val now: () -> Instant = Instant::now,
    /** What the network's reconfiguration is timed with: tests turn it by hand, with the timeouts' delays. */
    private val time: TimeSource = TimeSource.Monotonic,
) {
    /** What others may watch. */
    val running = RunningMachine(machine)

    private val inputs = Channel<Input>(Channel.UNLIMITED)
    private var active: List<Mode> = emptyList()
    private val entries = HashMap<Mode, Int>()
    private val timers = HashMap<Mode, List<Job>>()
    private var reconfiguration: Job? = null
    private var generation = 0

    /** What the machine watches of its modes' networks. */
    val networkWatch = NetworkWatch(machine)

    /** How this run matches each transition's events: some follow a value from one event to the next. */
    private val matchers = machine.eventPatterns.associateWith { it.matcher() }

    /** The network of the active modes, as last asked of the configurator. */
    private var network: Network? = null

    /** That network once done, with the connectors joining its links; null until then. */
    private var established: Established? = null

    private class Established(val network: Network, val connectors: Map<Link, List<String>>) {
        /**
         * Whether a breach was raised already: what follows from the same fault (lost, then unreachable) is logged
         * only.
         */
        var broken = false
    }

    /** Enters the initial modes, then handles inputs until [scope] ends. */
    fun start() {
        scope.launch(CoroutineName("modes ${machine.name}")) {
            val entering = listOf(machine.root) + machine.root.initialDescent
            log("mode ${machine.name}: starts in ${entering.last().path}")
            enter(entering, Reaction(engine, null))
            record(null, "start")
            if (entering.any { it.network != null }) reconfigure()
            for (input in inputs) handle(input)
        }
    }

    /**
     * Queues [event], delivered by the subscription watching for [patterns], if it is one of them. Each pattern matches
     * it once, here: a pattern that follows a value (a parameter's effective value) must see each event once, in order.
     */
    fun offer(event: RtcEvent, patterns: List<EventPattern<*>>) {
        if (networkWatch.owns(patterns)) {
            if (networkWatch.accepts(event, patterns)) inputs.trySend(Input.Watched(event, patterns))
            return
        }
        val matched = patterns.mapNotNull { pattern -> matchers[pattern]?.match(event)?.let { pattern to it } }.toMap()
        if (matched.isNotEmpty()) inputs.trySend(Input.Event(matched))
    }

    /** Reads what [patterns] follow of [node] before its first event is offered. */
    suspend fun prepare(patterns: List<EventPattern<*>>, node: Node) {
        patterns.forEach { matchers[it]?.prepare(node) }
    }

    private suspend fun handle(received: Input) {
        val input =
            when (received) {
                is Input.Watched -> breach(received) ?: return
                is Input.Outcome -> received.also { if (isCurrent(it)) noteOutcome(it) }
                else -> received
            }
        val reaction = Reaction(engine, input.event)
        val transition = if (isCurrent(input)) choose(input, reaction) else null
        if (transition == null) {
            running.notConsumed()
            logger.debug("machine {}: nothing in {} consumed {}", machine.name, active.last().path, describe(input))
            return
        }
        val from = active.last()
        val trigger = if (input is Input.Outcome || input is Input.Broken) describe(input) else transition.trigger
        val kept = active.indexOf(domainOf(transition.source, transition.target)) + 1
        val leaving = active.drop(kept)
        val entering = transition.target.lineage.drop(kept) + transition.target.initialDescent
        // Before any action runs, so that entry actions never race a reconfiguration for the modes being left.
        if ((leaving + entering).any { it.network != null }) {
            reconfiguration?.cancelAndJoin()
            generation++
            established = null
        }
        // Once the reconfiguration is stopped: from this line on, a transition without actions is done without
        // suspending, so a run stopped on it reports the new mode.
        log("mode ${from.path} -> ${entering.last().path} on $trigger")
        for (mode in leaving.asReversed()) {
            timers.remove(mode)?.forEach(Job::cancel)
            run("exit of ${mode.path}", mode.exitActions, reaction)
            active = active.dropLast(1)
        }
        transition.action?.let { run("action of ${transition.source.path} $transition", listOf(it), reaction) }
        enter(entering, reaction)
        record(from, trigger)
        if (entering.any { it.network != null }) reconfigure()
    }

    /**
     * Whether [input] still concerns the active modes: a timeout of a mode not left since, the latest reconfiguration's
     * outcome.
     */
    private fun isCurrent(input: Input): Boolean =
        when (input) {
            is Input.Event -> true
            is Input.Outcome -> input.generation == generation
            is Input.Broken,
            is Input.Watched -> true
            is Input.Timeout -> input.transition.source in active && entries[input.transition.source] == input.entry
        }

    private suspend fun choose(input: Input, reaction: Reaction): Transition? {
        for (mode in active.asReversed()) {
            for (transition in mode.transitions) {
                if (triggers(transition, input) && holds(transition, reaction)) return transition
            }
        }
        return null
    }

    private fun triggers(transition: Transition, input: Input): Boolean =
        when (val cause = transition.cause) {
            is Trigger.Event -> input is Input.Event && cause.pattern in input.matched
            is Trigger.Network ->
                when (cause.outcome) {
                    NetworkOutcome.DONE -> input is Input.Outcome && input.failure == null
                    NetworkOutcome.FAILED -> input is Input.Outcome && input.failure != null
                    NetworkOutcome.BROKEN -> input is Input.Broken
                }
            is Trigger.Timeout -> input is Input.Timeout && input.transition === transition
        }

    private suspend fun holds(transition: Transition, reaction: Reaction): Boolean =
        catchFailure({ ScriptCallSite.tracking { transition.guards.all { guard -> reaction.guard() } } }) { e ->
            failed("guard of ${transition.source.path} $transition", e)
            false
        }

    private suspend fun enter(modes: List<Mode>, reaction: Reaction) {
        for (mode in modes) {
            active = active + mode
            val entry = (entries[mode] ?: 0) + 1
            entries[mode] = entry
            run("entry of ${mode.path}", mode.entryActions, reaction)
            timers[mode] =
                mode.transitions.mapNotNull { transition ->
                    (transition.cause as? Trigger.Timeout)?.let { timeout ->
                        scope.launch {
                            delay(timeout.delay)
                            inputs.send(Input.Timeout(transition, entry))
                        }
                    }
                }
        }
    }

    private fun record(from: Mode?, trigger: String) {
        running.moved(ModeTransition(from?.path, active.last().path, trigger, now()))
    }

    /** A network done is watched from now on: what it names that exists now is subscribed. */
    private suspend fun noteOutcome(outcome: Input.Outcome) {
        val network = network ?: return
        val connectors = outcome.connectors ?: return
        established = Established(network, connectors)
        watchNetwork(this)
    }

    /** [watched] as the breach of the network in force it is, logged; null when it breaks nothing it requires. */
    private fun breach(watched: Input.Watched): Input.Broken? {
        val current = established ?: return null
        val reason =
            networkWatch.breach(current.network, current.connectors, watched.event, watched.patterns) ?: return null
        log("mode ${active.last().path}: network broken: $reason")
        if (current.broken) return null
        current.broken = true
        return Input.Broken(reason)
    }

    private suspend fun reconfigure() {
        val network = active.mapNotNull { it.network }.reduce(Network::overriddenBy).also { network = it }
        val mode = active.last().path
        val current = generation
        reconfiguration =
            scope.launch(CoroutineName("network of $mode")) {
                log("mode $mode: bringing the system to its network")
                val started = time.markNow()
                val outcome = configurator.apply(network)
                val took = started.elapsedNow().inWholeMilliseconds
                val failure = (outcome as? Configurator.Outcome.Failed)?.reason
                val done = outcome as? Configurator.Outcome.Done
                log(
                    "mode $mode: network " +
                        (failure?.let { "failed after $took ms: $it" }
                            ?: "done (${done!!.steps.size} steps in $took ms)")
                )
                inputs.send(Input.Outcome(current, failure, done?.connectors))
            }
    }

    private suspend fun run(what: String, actions: List<suspend Reaction.() -> Unit>, reaction: Reaction) {
        for (action in actions) {
            catchFailure({ ScriptCallSite.tracking { reaction.action() } }) { e -> failed(what, e) }
        }
    }

    private fun describe(input: Input): String =
        when (input) {
            is Input.Event -> input.matched.keys.first().description
            is Input.Outcome -> input.failure?.let { "failed: $it" } ?: "done"
            is Input.Broken -> "networkBroken: ${input.reason}"
            is Input.Watched -> "a change of the network"
            is Input.Timeout -> "${input.transition.trigger} in ${input.transition.source.path}"
        }

    /**
     * The innermost mode a transition leaves active: the deepest proper ancestor of both ends (the top, for the top's
     * own transitions).
     */
    private fun domainOf(source: Mode, target: Mode): Mode =
        if (source.parent == null) source else source.lineage.dropLast(1).last { it in target.lineage.dropLast(1) }

    private sealed class Input {
        open val event: RtcEvent?
            get() = null

        /** An event as each pattern it matched sees it. */
        class Event(val matched: Map<EventPattern<*>, RtcEvent>) : Input() {
            override val event: RtcEvent
                get() = matched.values.first()
        }

        class Outcome(val generation: Int, val failure: String?, val connectors: Map<Link, List<String>>?) : Input()

        /** An event of a network's components, to be checked against the network in force. */
        class Watched(override val event: RtcEvent, val patterns: List<EventPattern<*>>) : Input()

        class Broken(val reason: String) : Input()

        class Timeout(val transition: Transition, val entry: Int) : Input()
    }

    private companion object {
        val logger = LoggerFactory.getLogger(MachineInterpreter::class.java)
    }
}
