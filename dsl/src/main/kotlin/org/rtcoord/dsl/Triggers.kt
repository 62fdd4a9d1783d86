@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl

import kotlin.time.Duration
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.FsmStateChanged
import org.rtcoord.HeartbeatLost
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.LifeCycle
import org.rtcoord.LogLevel
import org.rtcoord.LogRecord
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerReturned
import org.rtcoord.Node
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortData
import org.rtcoord.PortDisconnected
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcPath
import org.rtcoord.StateChanged
import org.rtcoord.dsl.internal.DeclaredGuard
import org.rtcoord.dsl.script.LogLevelNames

/**
 * A guard: the rule fires only when it returns true for the event. It runs when the rule's turn to handle the event
 * comes, just before its handler, and what it reads of the system (a component's state, a parameter) is read then: the
 * system as the handler will find it, which may have moved on since the event happened. What held at the event is in
 * the event itself (its source, its new state).
 */
public typealias Guard = suspend Reaction.(RtcEvent) -> Boolean

/** The events of a component a rule can react to: `on(component("laser0.rtc")).state(ERROR) { ... }`. */
@RtcDsl
public class ComponentTriggers
internal constructor(
    private val owner: Coordination,
    private val target: ComponentRef,
    private val guards: List<Guard>,
) {
    /**
     * Narrows the rule to events for which [guard] holds: `on(component("laser0.rtc")).where {
     * component("odo_localise0.rtc").state() != ACTIVE }.state(ERROR) { ... }`. The guard reads the system when the
     * handler is about to run, not as it was when the event happened (see [Guard]); to act on the event's own facts,
     * read the event.
     */
    public fun where(guard: Guard): ComponentTriggers =
        ComponentTriggers(owner, target, guards + DeclaredGuard.of(guard))

    /**
     * When the component enters [state] (in any execution context). Edge-triggered by default: a component already in
     * [state] when the coordinator starts is left alone until it enters it again. With [includeCurrent], the rule is
     * level-triggered at the start: a component already in [state] fires it once, as a [StateChanged] from [state] to
     * [state], so a coordinator (re)started after a fault still reacts to it; so does a component re-created in
     * [state]: `on(component("laser0.rtc")).state(ERROR, includeCurrent = true) { ... }`.
     */
    public fun state(
        state: LifeCycle,
        includeCurrent: Boolean = false,
        handler: suspend Reaction.(StateChanged) -> Unit,
    ): Unit =
        add(if (includeCurrent) EventPatterns.inState(target, state) else EventPatterns.state(target, state), handler)

    /**
     * When its FSM (an OpenRTM-aist 2.0 FSM component's, told by its FSM4RTC observer) enters [state]:
     * `on(component("Microwave0.rtc")).fsmState("Cooking") { ... }`. A transition enters each state on the way down to
     * its target: from `Disabled`, `close` enters `Operational`, then `Idle` below it: both are published, in that
     * order, and fire the rules of both (each rule's handler in a coroutine of its own, so one rule's does not wait for
     * another's). A component whose observer cannot tell its FSM's state never fires it (see
     * [org.rtcoord.ComponentEntry.fsm] for why).
     */
    public fun fsmState(state: String, handler: suspend Reaction.(FsmStateChanged) -> Unit): Unit =
        add(EventPatterns.fsmState(target, state), handler)

    /** On every lifecycle change. */
    public fun stateChanged(handler: suspend Reaction.(StateChanged) -> Unit): Unit =
        add(EventPatterns.stateChanged(target), handler)

    /**
     * When the effective value of configuration parameter [name] changes, its value in the active set: set there, or
     * changed by a switch to a set that holds another value (whoever switches). `configParam("gain") { old, new -> ...
     * }`; the rule's [Reaction.event] is a [ParameterChanged] naming the active set.
     */
    public fun configParam(name: String, handler: suspend Reaction.(old: String?, new: String?) -> Unit): Unit =
        add(EventPatterns.configParam(target, name)) { handler(it.old, it.new) }

    /**
     * When configuration parameter [name] changes in any set, active or not: `configParamInAnySet("gain") { set, old,
     * new -> ... }` with the id of the set that changed. A switch of the active set is no change here (see
     * [configParam] for the value the component uses).
     */
    public fun configParamInAnySet(
        name: String,
        handler: suspend Reaction.(set: String, old: String?, new: String?) -> Unit,
    ): Unit = add(EventPatterns.configParamInAnySet(target, name)) { handler(it.set, it.old, it.new) }

    /**
     * When another configuration set becomes active: `configSetActivated { old, new -> ... }` with the sets' ids. A
     * write that leaves no set active until the same set is activated again is no switch; [old] is null only when no
     * set was ever seen active.
     */
    public fun configSetActivated(handler: suspend Reaction.(old: String?, new: String) -> Unit): Unit =
        add(EventPatterns.configSetActivated(target)) { handler(it.old, checkNotNull(it.new)) }

    /** When the rate of one of its execution contexts changes. */
    public fun rateChanged(handler: suspend Reaction.(old: Double, new: Double) -> Unit): Unit =
        add(EventPatterns.rateChanged(target)) { handler(it.old, it.new) }

    /** When one of its ports gets a connection. */
    public fun connected(handler: suspend Reaction.(PortConnected) -> Unit): Unit =
        add(EventPatterns.connected(target), handler)

    /** When one of its ports loses a connection. */
    public fun disconnected(handler: suspend Reaction.(PortDisconnected) -> Unit): Unit =
        add(EventPatterns.disconnected(target), handler)

    /** When its heartbeats (or answers to polls) stop. */
    public fun lost(handler: suspend Reaction.(HeartbeatLost) -> Unit): Unit = add(EventPatterns.lost(target), handler)

    /** When it cannot be reached at all. */
    public fun zombie(handler: suspend Reaction.(BecameZombie) -> Unit): Unit =
        add(EventPatterns.zombie(target), handler)

    /** When it answers again after it was lost. */
    public fun recovered(handler: suspend Reaction.(Recovered) -> Unit): Unit =
        add(EventPatterns.recovered(target), handler)

    /** When it exits. */
    public fun finalized(handler: suspend Reaction.(ComponentFinalized) -> Unit): Unit =
        add(EventPatterns.finalized(target), handler)

    /**
     * When the component logs a record at [level] or above (OpenRTM-aist's levels: [LogLevel.WARN] hears WARN, ERROR
     * and FATAL) whose message [matching] finds, if given; with [atLeast], once it has logged that many such records
     * within [within]: `logged(WARN, matching = Regex("timeout"), atLeast = 3, within = 10.seconds) { record -> ... }`,
     * before it fails. Records reach a coordinator through a log input of its tree (`rtcoord run --logs-listen`, or
     * [org.rtcoord.RtcTree.listenForLogs]) that the component's process sends to.
     */
    public fun logged(
        level: LogLevel = LogLevel.WARN,
        matching: Regex? = null,
        atLeast: Int = 1,
        within: Duration = Duration.INFINITE,
        handler: suspend Reaction.(LogRecord) -> Unit,
    ): Unit = add(EventPatterns.logged(Target.Component(target), "$target", level, matching, atLeast, within), handler)

    /** [logged] at [LogLevel.ERROR], for a script's bare `logged(ERROR)` (see [LogLevelNames]). */
    public fun logged(
        level: LifeCycle,
        matching: Regex? = null,
        atLeast: Int = 1,
        within: Duration = Duration.INFINITE,
        handler: suspend Reaction.(LogRecord) -> Unit,
    ): Unit = logged(LogLevelNames.of(level), matching, atLeast, within, handler)

    private fun <E : RtcEvent> add(pattern: EventPattern<E>, handler: suspend Reaction.(E) -> Unit) =
        owner.add(pattern.rule(guards, handler))
}

/** The events of one port: `on(port("gyro0.rtc:gyro")).disconnected { ... }`. */
@RtcDsl
public class PortTriggers
internal constructor(private val owner: Coordination, private val target: PortRef, private val guards: List<Guard>) {
    /** Narrows the rule to events for which [guard] holds, read when the handler is about to run (see [Guard]). */
    public fun where(guard: Guard): PortTriggers = PortTriggers(owner, target, guards + DeclaredGuard.of(guard))

    /** When the port gets a connection. */
    public fun connected(handler: suspend Reaction.(PortConnected) -> Unit): Unit =
        owner.add(EventPatterns.connected(target).rule(guards, handler))

    /** When the port loses a connection. */
    public fun disconnected(handler: suspend Reaction.(PortDisconnected) -> Unit): Unit =
        owner.add(EventPatterns.disconnected(target).rule(guards, handler))

    /**
     * On each sample of type [T] the out-port sends: `on(port("laser0.rtc:laser")).data<TimedDoubleSeq> { scan -> ...
     * }`. The coordinator taps the port (one tap per port, see [org.rtcoord.Port.tap]); while the handler runs, only
     * the newest sample waits (LATEST), so a fast stream never queues behind a slow handler. Samples of another type
     * are ignored; [org.rtcoord.UnknownData] takes any type not decoded. Guards do not apply to data rules.
     */
    public inline fun <reified T : PortData> data(noinline handler: suspend Reaction.(T) -> Unit): Unit =
        data(T::class.java, handler)

    /** [data] with the type as a class, for callers that do not know it at compile time. */
    public fun <T : PortData> data(type: Class<T>, handler: suspend Reaction.(T) -> Unit): Unit =
        owner.addData(DataRule.Samples(target, type, handler))

    /**
     * When the out-port sends nothing for [limit] while its component is ACTIVE: the data-liveness watchdog, for a
     * sensor that stays ACTIVE but stopped publishing: `on(port("laser0.rtc:laser")).silentFor(500.milliseconds) { ...
     * }`. Fires once per silence; the next sample re-arms it. Time while the component is not ACTIVE does not count.
     */
    public fun silentFor(limit: Duration, handler: suspend Reaction.() -> Unit) {
        require(limit.isPositive()) { "silentFor needs a positive duration, was $limit" }
        owner.addData(DataRule.Silence(target, limit, handler))
    }

    /**
     * When the out-port sends fewer than [rate] samples a second (counted over the last second) while its component is
     * ACTIVE: `on(port("laser0.rtc:laser")).rateBelow(5.0) { rate -> ... }`. Fires once per drop; a rate back at [rate]
     * re-arms it.
     */
    public fun rateBelow(rate: Double, handler: suspend Reaction.(rate: Double) -> Unit) {
        require(rate > 0) { "rateBelow needs a positive rate, was $rate" }
        owner.addData(DataRule.RateBelow(target, rate, handler))
    }
}

/** What a manager does: `on(manager()).created { name -> ... }`. */
@RtcDsl
public class ManagerTriggers
internal constructor(private val owner: Coordination, private val target: ManagerRef, private val guards: List<Guard>) {
    /** Narrows the rule to events for which [guard] holds, read when the handler is about to run (see [Guard]). */
    public fun where(guard: Guard): ManagerTriggers = ManagerTriggers(owner, target, guards + DeclaredGuard.of(guard))

    /** When the manager (or one of its slaves) creates a component. */
    public fun created(handler: suspend Reaction.(instanceName: String) -> Unit): Unit =
        owner.add(EventPatterns.created(target).rule(guards) { handler(it.instanceName) })

    /** When a component it hosted is deleted. */
    public fun deleted(handler: suspend Reaction.(instanceName: String) -> Unit): Unit =
        owner.add(EventPatterns.deleted(target).rule(guards) { handler(it.instanceName) })

    /**
     * When the manager itself stops answering (its process died or hangs; a slave's death is not its): `died { event ->
     * log("lost ${event.components.size} components") }`, once per death.
     */
    public fun died(handler: suspend Reaction.(ManagerDied) -> Unit): Unit =
        owner.add(EventPatterns.died(target).rule(guards, handler))

    /** When the manager, said dead, answers again. */
    public fun returned(handler: suspend Reaction.(ManagerReturned) -> Unit): Unit =
        owner.add(EventPatterns.returned(target).rule(guards, handler))

    /**
     * When the manager's process, or a component it hosts, logs a record at [level] or above; [matching], [atLeast] and
     * [within] as in [ComponentTriggers.logged].
     */
    public fun logged(
        level: LogLevel = LogLevel.WARN,
        matching: Regex? = null,
        atLeast: Int = 1,
        within: Duration = Duration.INFINITE,
        handler: suspend Reaction.(LogRecord) -> Unit,
    ): Unit =
        owner.add(
            EventPatterns.logged(Target.Manager(target), "$target", level, matching, atLeast, within)
                .rule(guards, handler)
        )

    /** [logged] at [LogLevel.ERROR], for a script's bare `logged(ERROR)` (see [LogLevelNames]). */
    public fun logged(
        level: LifeCycle,
        matching: Regex? = null,
        atLeast: Int = 1,
        within: Duration = Duration.INFINITE,
        handler: suspend Reaction.(LogRecord) -> Unit,
    ): Unit = logged(LogLevelNames.of(level), matching, atLeast, within, handler)
}

/** Bindings appearing and vanishing in a naming context: `on(context("/localhost/host.host_cxt")).appeared { ... }`. */
@RtcDsl
public class ContextTriggers
internal constructor(private val owner: Coordination, private val target: ContextRef, private val guards: List<Guard>) {
    /** Narrows the rule to events for which [guard] holds, read when the handler is about to run (see [Guard]). */
    public fun where(guard: Guard): ContextTriggers = ContextTriggers(owner, target, guards + DeclaredGuard.of(guard))

    /** When a binding appears in the context. */
    public fun appeared(handler: suspend Reaction.(Node) -> Unit): Unit =
        owner.add(EventPatterns.appeared(target).rule(guards) { handler(it.child) })

    /** When a binding vanishes from the context. */
    public fun vanished(handler: suspend Reaction.(RtcPath) -> Unit): Unit =
        owner.add(EventPatterns.vanished(target).rule(guards) { handler(it.child) })

    /**
     * When the name server the context is on stops answering (`on(context("/localhost")).unreachable { }`): until it
     * answers again nothing registered on it can be found, although the components may still run.
     */
    public fun unreachable(handler: suspend Reaction.(NameServerLost) -> Unit): Unit =
        owner.add(EventPatterns.unreachable(target).rule(guards, handler))

    /** When the name server the context is on answers again; the event says how long it was gone. */
    public fun reachable(handler: suspend Reaction.(NameServerReturned) -> Unit): Unit =
        owner.add(EventPatterns.reachable(target).rule(guards, handler))
}

/**
 * Every log record the tree's log inputs receive, from any sender, listed or not: `on(logs()).level(ERROR) { record ->
 * ... }`.
 */
@RtcDsl
public class LogTriggers internal constructor(private val owner: Coordination, private val guards: List<Guard>) {
    /** Narrows the rule to records for which [guard] holds, read when the handler is about to run (see [Guard]). */
    public fun where(guard: Guard): LogTriggers = LogTriggers(owner, guards + DeclaredGuard.of(guard))

    /**
     * When any sender logs a record at [level] or above; [matching], [atLeast] (counted for each sender) and [within]
     * as in [ComponentTriggers.logged].
     */
    public fun level(
        level: LogLevel,
        matching: Regex? = null,
        atLeast: Int = 1,
        within: Duration = Duration.INFINITE,
        handler: suspend Reaction.(LogRecord) -> Unit,
    ): Unit =
        owner.add(EventPatterns.logged(Target.Logs, "anyone", level, matching, atLeast, within).rule(guards, handler))

    /** [level] at [LogLevel.ERROR], for a script's bare `level(ERROR)` (see [LogLevelNames]). */
    public fun level(
        level: LifeCycle,
        matching: Regex? = null,
        atLeast: Int = 1,
        within: Duration = Duration.INFINITE,
        handler: suspend Reaction.(LogRecord) -> Unit,
    ): Unit = level(LogLevelNames.of(level), matching, atLeast, within, handler)
}
