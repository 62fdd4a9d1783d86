package org.rtcoord.dsl

import kotlin.time.Duration
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ContextRateChanged
import org.rtcoord.FsmStateChanged
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.LogLevel
import org.rtcoord.LogRecord
import org.rtcoord.ManagerComponentChanged
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerReturned
import org.rtcoord.Node
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcPath
import org.rtcoord.StateChanged

/**
 * One kind of event of one target (a component entering ERROR, a port losing a connection): what rules and mode
 * transitions are triggered by. [description] is how scripts, logs and `check` name it. Most patterns take the events
 * of their [type] as they come; one that follows a value, or a condition it also fires on when first seen, reads events
 * of a wider [watched] type through a [reading] of its own, which each run of a plan makes afresh.
 */
internal class EventPattern<E : RtcEvent>(
    val description: String,
    val target: Target,
    val type: Class<E>,
    val watched: Class<out RtcEvent> = type,
    private val reading: (() -> EventReading<E>)? = null,
    /** The configuration parameter the pattern is about, if any: what `check` looks for on the live component. */
    val parameter: String? = null,
    val matches: (E) -> Boolean,
) {
    /** A rule running [handler] on these events when every guard holds. */
    fun rule(guards: List<Guard>, handler: suspend Reaction.(E) -> Unit): Rule<E> = Rule(this, guards, handler)

    /** A matcher for one subscriber of one run: what it follows starts from nothing. */
    fun matcher(): EventMatcher<E> = EventMatcher(this, reading?.invoke())

    override fun toString(): String = description
}

/**
 * How a pattern that follows a value (a parameter's effective value, the active set, being in a state) reads events: it
 * reads a component's value before the first event, and turns each event into one of its kind, or drops it.
 */
internal interface EventReading<E : RtcEvent> {
    /**
     * Reads [node]'s value now, so that its first change is measured from it; returns the event its present condition
     * amounts to for a level-triggered reading, null otherwise.
     */
    suspend fun prepare(node: Node): E?

    /** [event] as a change of the value followed; null when it changes nothing. */
    fun translate(event: RtcEvent): E?
}

/** One subscriber's view of a [pattern]: each event must be matched once, in order, as a [reading] follows a value. */
internal class EventMatcher<E : RtcEvent>(val pattern: EventPattern<E>, private val reading: EventReading<E>?) {
    /**
     * Reads what the pattern follows of [node], before [node]'s first event reaches [match]; returns the event its
     * present condition amounts to, if any.
     */
    suspend fun prepare(node: Node): E? = reading?.prepare(node)?.takeIf(pattern.matches)

    /** [event] as one of the pattern's, or null when it is not one. */
    fun match(event: RtcEvent): E? {
        val translated =
            if (reading != null) reading.translate(event)
            else event.takeIf(pattern.type::isInstance)?.let(pattern.type::cast)
        return translated?.takeIf(pattern.matches)
    }
}

/** The event kinds of each target, shared by rules and transitions so that both name and match them alike. */
internal object EventPatterns {
    fun state(target: ComponentRef, state: LifeCycle) =
        EventPattern("$target enters $state", Target.Component(target), StateChanged::class.java) { it.new == state }

    /**
     * [state], and a component already in [state] when watched: a [StateChanged] from [state] to itself in its default
     * context.
     */
    fun inState(target: ComponentRef, state: LifeCycle) =
        EventPattern(
            "$target is in or enters $state",
            Target.Component(target),
            StateChanged::class.java,
            reading = { InState(state) },
        ) {
            it.new == state
        }

    fun fsmState(target: ComponentRef, state: String) =
        EventPattern("$target's FSM enters $state", Target.Component(target), FsmStateChanged::class.java) {
            it.new == state
        }

    fun stateChanged(target: ComponentRef) =
        EventPattern("$target changes state", Target.Component(target), StateChanged::class.java) { true }

    /**
     * Changes of the effective value of [name]: in the active set, or by a switch to a set that holds another value.
     */
    fun configParam(target: ComponentRef, name: String): EventPattern<ParameterChanged> {
        return EventPattern(
            "$target parameter $name changes",
            Target.Component(target),
            ParameterChanged::class.java,
            watched = RtcEvent::class.java,
            reading = { EffectiveValue(name) },
            parameter = name,
        ) {
            true
        }
    }

    /** Changes of [name] in any set, as the component reports them. */
    fun configParamInAnySet(target: ComponentRef, name: String) =
        EventPattern(
            "$target parameter $name changes in any set",
            Target.Component(target),
            ParameterChanged::class.java,
            parameter = name,
        ) {
            it.name == name
        }

    fun configSetActivated(target: ComponentRef): EventPattern<ConfigurationSetActivated> {
        return EventPattern(
            "$target activates a configuration set",
            Target.Component(target),
            ConfigurationSetActivated::class.java,
            reading = ::ActiveSetSwitch,
        ) {
            true
        }
    }

    fun rateChanged(target: ComponentRef) =
        EventPattern("$target rate changes", Target.Component(target), ContextRateChanged::class.java) { true }

    fun connected(target: ComponentRef) =
        EventPattern("$target connects", Target.Component(target), PortConnected::class.java) { true }

    fun disconnected(target: ComponentRef) =
        EventPattern("$target disconnects", Target.Component(target), PortDisconnected::class.java) { true }

    fun lost(target: ComponentRef) =
        EventPattern("$target is lost", Target.Component(target), HeartbeatLost::class.java) { true }

    fun zombie(target: ComponentRef) =
        EventPattern("$target becomes a zombie", Target.Component(target), BecameZombie::class.java) { true }

    fun recovered(target: ComponentRef) =
        EventPattern("$target recovers", Target.Component(target), Recovered::class.java) { true }

    fun finalized(target: ComponentRef) =
        EventPattern("$target exits", Target.Component(target), ComponentFinalized::class.java) { true }

    fun connected(target: PortRef) =
        EventPattern("$target connects", Target.Port(target), PortConnected::class.java) { it.port == target.name }

    fun disconnected(target: PortRef) =
        EventPattern("$target disconnects", Target.Port(target), PortDisconnected::class.java) {
            it.port == target.name
        }

    fun created(target: ManagerRef) =
        EventPattern("$target creates a component", Target.Manager(target), ManagerComponentChanged::class.java) {
            it.created
        }

    fun deleted(target: ManagerRef) =
        EventPattern("$target deletes a component", Target.Manager(target), ManagerComponentChanged::class.java) {
            !it.created
        }

    fun died(target: ManagerRef) =
        EventPattern("$target dies", Target.Manager(target), ManagerDied::class.java) { target.names(it.source) }

    fun returned(target: ManagerRef) =
        EventPattern("$target answers again", Target.Manager(target), ManagerReturned::class.java) {
            target.names(it.source)
        }

    fun appeared(target: ContextRef) =
        EventPattern("$target gains a binding", Target.Context(target), NodeAppeared::class.java) {
            it.source.path.toString() == RtcPath(target.path).toString()
        }

    fun vanished(target: ContextRef) =
        EventPattern("$target loses a binding", Target.Context(target), NodeVanished::class.java) {
            it.source.path.toString() == RtcPath(target.path).toString()
        }

    fun unreachable(target: ContextRef) =
        EventPattern("$target's name server stops answering", Target.Context(target), NameServerLost::class.java) {
            it.source.address == RtcPath(target.path).nameServer
        }

    fun reachable(target: ContextRef) =
        EventPattern("$target's name server answers again", Target.Context(target), NameServerReturned::class.java) {
            it.source.address == RtcPath(target.path).nameServer
        }

    /**
     * Records from [target] (a component's, a manager's or, for [Target.Logs], anyone's: [sender] names it) at [level]
     * or above, whose message [matching] finds, [atLeast] of them within [within] (see [LogBurst]).
     */
    fun logged(
        target: Target,
        sender: String,
        level: LogLevel,
        matching: Regex?,
        atLeast: Int,
        within: Duration,
    ): EventPattern<LogRecord> {
        require(atLeast >= 1) { "logged needs atLeast of 1 or more, was $atLeast" }
        require(within.isPositive()) { "logged needs a positive window, was $within" }
        val matches = { record: LogRecord ->
            record.level.atLeast(level) && (matching == null || matching.containsMatchIn(record.message))
        }
        val what = buildString {
            append("$sender logs")
            append(" at $level or above")
            if (matching != null) append(" matching /${matching.pattern}/")
            if (atLeast > 1) append(", $atLeast times")
            if (within.isFinite()) append(" within $within")
        }
        return if (atLeast == 1) EventPattern(what, target, LogRecord::class.java, matches = matches)
        else
            EventPattern(what, target, LogRecord::class.java, reading = { LogBurst(atLeast, within, matches) }) { true }
    }
}
