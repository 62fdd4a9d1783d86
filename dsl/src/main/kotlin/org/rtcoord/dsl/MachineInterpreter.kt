package org.rtcoord.dsl

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import org.rtcoord.RtcEvent
import org.slf4j.LoggerFactory
import java.time.Instant
import kotlin.time.TimeSource

/**
 * Runs a [ModeMachine], UML/SCXML style. Inputs (watched events, reconfiguration outcomes, timeouts)
 * queue without limit and are handled one at a time, each to completion: the first transition of the
 * innermost active mode whose trigger matches and whose guards hold is taken (outer modes' transitions
 * apply when no inner one does); exits run innermost first up to the least common ancestor of source
 * and target, then the transition's action, then entries outermost first down to the target and its
 * initial modes. An input no transition takes is counted and logged at debug level, never dropped
 * unseen.
 *
 * Entering a mode that declares a network brings the system to the merged network of the active modes
 * through the [Configurator], in the background, and queues `done` or `failed`. Leaving or entering a
 * mode that declares one cancels a reconfiguration still under way: its outcome never arrives.
 * A mode's `after` timers start once its entry actions ran and stop when it is left.
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
    private val now: () -> Instant = Instant::now,
) {
    /** What others may watch. */
    val running = RunningMachine(machine)

    private val inputs = Channel<Input>(Channel.UNLIMITED)
    private var active: List<Mode> = emptyList()
    private val entries = HashMap<Mode, Int>()
    private val timers = HashMap<Mode, List<Job>>()
    private var reconfiguration: Job? = null
    private var generation = 0

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

    /** Queues [event], delivered by the subscription watching for [patterns], if it is one of them. */
    fun offer(event: RtcEvent, patterns: List<EventPattern<*>>) {
        if (patterns.any { it.accepts(event) }) inputs.trySend(Input.Event(event, patterns))
    }

    private suspend fun handle(input: Input) {
        val reaction = Reaction(engine, input.event)
        val transition = if (isCurrent(input)) choose(input, reaction) else null
        if (transition == null) {
            running.notConsumed()
            logger.debug("machine {}: nothing in {} consumed {}", machine.name, active.last().path, describe(input))
            return
        }
        val from = active.last()
        val trigger = if (input is Input.Outcome) describe(input) else transition.trigger
        val kept = active.indexOf(domainOf(transition.source, transition.target)) + 1
        val leaving = active.drop(kept)
        val entering = transition.target.lineage.drop(kept) + transition.target.initialDescent
        log("mode ${from.path} -> ${entering.last().path} on $trigger")
        // Before any action runs, so that entry actions never race a reconfiguration for the modes being left.
        if ((leaving + entering).any { it.network != null }) {
            reconfiguration?.cancelAndJoin()
            generation++
        }
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

    /** Whether [input] still concerns the active modes: a timeout of a mode not left since, the latest reconfiguration's outcome. */
    private fun isCurrent(input: Input): Boolean = when (input) {
        is Input.Event -> true
        is Input.Outcome -> input.generation == generation
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

    private fun triggers(transition: Transition, input: Input): Boolean = when (val cause = transition.cause) {
        is Trigger.Event -> input is Input.Event && cause.pattern in input.patterns && cause.pattern.accepts(input.event)
        is Trigger.Network -> input is Input.Outcome && (input.failure == null) == (cause.outcome == NetworkOutcome.DONE)
        is Trigger.Timeout -> input is Input.Timeout && input.transition === transition
    }

    private suspend fun holds(transition: Transition, reaction: Reaction): Boolean = try {
        transition.guards.all { guard -> reaction.guard() }
    } catch (e: CancellationException) {
        throw e
    } catch (e: Exception) {
        failed("guard of ${transition.source.path} $transition", e)
        false
    }

    private suspend fun enter(modes: List<Mode>, reaction: Reaction) {
        for (mode in modes) {
            active = active + mode
            val entry = (entries[mode] ?: 0) + 1
            entries[mode] = entry
            run("entry of ${mode.path}", mode.entryActions, reaction)
            timers[mode] = mode.transitions.mapNotNull { transition ->
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

    private suspend fun reconfigure() {
        val network = active.mapNotNull { it.network }.reduce(Network::overriddenBy)
        val mode = active.last().path
        val current = generation
        reconfiguration = scope.launch(CoroutineName("network of $mode")) {
            log("mode $mode: bringing the system to its network")
            val started = TimeSource.Monotonic.markNow()
            val outcome = configurator.apply(network)
            val took = started.elapsedNow().inWholeMilliseconds
            val failure = (outcome as? Configurator.Outcome.Failed)?.reason
            log("mode $mode: network " + (failure?.let { "failed after $took ms: $it" } ?: "done (${(outcome as Configurator.Outcome.Done).steps.size} steps in $took ms)"))
            inputs.send(Input.Outcome(current, failure))
        }
    }

    private suspend fun run(what: String, actions: List<suspend Reaction.() -> Unit>, reaction: Reaction) {
        for (action in actions) {
            try {
                reaction.action()
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                failed(what, e)
            }
        }
    }

    private fun describe(input: Input): String = when (input) {
        is Input.Event -> input.patterns.first { it.accepts(input.event) }.description
        is Input.Outcome -> input.failure?.let { "failed: $it" } ?: "done"
        is Input.Timeout -> "${input.transition.trigger} in ${input.transition.source.path}"
    }

    /** The innermost mode a transition leaves active: the deepest proper ancestor of both ends (the top, for the top's own transitions). */
    private fun domainOf(source: Mode, target: Mode): Mode =
        if (source.parent == null) source else source.lineage.dropLast(1).last { it in target.lineage.dropLast(1) }

    private sealed class Input {
        open val event: RtcEvent? get() = null

        class Event(override val event: RtcEvent, val patterns: List<EventPattern<*>>) : Input()

        class Outcome(val generation: Int, val failure: String?) : Input()

        class Timeout(val transition: Transition, val entry: Int) : Input()
    }

    private companion object {
        val logger = LoggerFactory.getLogger(MachineInterpreter::class.java)
    }
}
