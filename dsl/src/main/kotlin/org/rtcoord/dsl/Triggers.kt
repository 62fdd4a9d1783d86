package org.rtcoord.dsl

import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ContextRateChanged
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerComponentChanged
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

/** A guard: the rule fires only when it returns true for the event. */
public typealias Guard = suspend Reaction.(RtcEvent) -> Boolean

/** The events of a component a rule can react to: `on(component("laser0.rtc")).state(ERROR) { ... }`. */
@RtcDsl
public class ComponentTriggers internal constructor(
    private val owner: Coordination,
    private val target: ComponentRef,
    private val guards: List<Guard>,
) {
    /** Narrows the rule to events for which [guard] holds. */
    public fun where(guard: Guard): ComponentTriggers = ComponentTriggers(owner, target, guards + guard)

    /** When the component enters [state] (in any execution context). */
    public fun state(state: LifeCycle, handler: suspend Reaction.(StateChanged) -> Unit): Unit =
        rule("$target enters $state", StateChanged::class.java, { it.new == state }, handler)

    /** On every lifecycle change. */
    public fun stateChanged(handler: suspend Reaction.(StateChanged) -> Unit): Unit =
        rule("$target changes state", StateChanged::class.java, { true }, handler)

    /** When configuration parameter [name] changes (in any set): `configParam("gain") { old, new -> ... }`. */
    public fun configParam(name: String, handler: suspend Reaction.(old: String?, new: String?) -> Unit): Unit =
        rule("$target parameter $name changes", ParameterChanged::class.java, { it.name == name }) { handler(it.old, it.new) }

    /** When the rate of one of its execution contexts changes. */
    public fun rateChanged(handler: suspend Reaction.(old: Double, new: Double) -> Unit): Unit =
        rule("$target rate changes", ContextRateChanged::class.java, { true }) { handler(it.old, it.new) }

    /** When one of its ports gets a connection. */
    public fun connected(handler: suspend Reaction.(PortConnected) -> Unit): Unit =
        rule("$target connects", PortConnected::class.java, { true }, handler)

    /** When one of its ports loses a connection. */
    public fun disconnected(handler: suspend Reaction.(PortDisconnected) -> Unit): Unit =
        rule("$target disconnects", PortDisconnected::class.java, { true }, handler)

    /** When its heartbeats (or answers to polls) stop. */
    public fun lost(handler: suspend Reaction.(HeartbeatLost) -> Unit): Unit =
        rule("$target is lost", HeartbeatLost::class.java, { true }, handler)

    /** When it cannot be reached at all. */
    public fun zombie(handler: suspend Reaction.(BecameZombie) -> Unit): Unit =
        rule("$target becomes a zombie", BecameZombie::class.java, { true }, handler)

    /** When it answers again after it was lost. */
    public fun recovered(handler: suspend Reaction.(Recovered) -> Unit): Unit =
        rule("$target recovers", Recovered::class.java, { true }, handler)

    /** When it exits. */
    public fun finalized(handler: suspend Reaction.(ComponentFinalized) -> Unit): Unit =
        rule("$target exits", ComponentFinalized::class.java, { true }, handler)

    private fun <E : RtcEvent> rule(description: String, type: Class<E>, matches: (E) -> Boolean, handler: suspend Reaction.(E) -> Unit) =
        owner.add(Rule(description, Target.Component(target), type, matches, guards, handler))
}

/** The events of one port: `on(port("gyro0.rtc:gyro")).disconnected { ... }`. */
@RtcDsl
public class PortTriggers internal constructor(private val owner: Coordination, private val target: PortRef, private val guards: List<Guard>) {
    /** Narrows the rule to events for which [guard] holds. */
    public fun where(guard: Guard): PortTriggers = PortTriggers(owner, target, guards + guard)

    /** When the port gets a connection. */
    public fun connected(handler: suspend Reaction.(PortConnected) -> Unit): Unit =
        owner.add(Rule("$target connects", Target.Port(target), PortConnected::class.java, { it.port == target.name }, guards, handler))

    /** When the port loses a connection. */
    public fun disconnected(handler: suspend Reaction.(PortDisconnected) -> Unit): Unit =
        owner.add(Rule("$target disconnects", Target.Port(target), PortDisconnected::class.java, { it.port == target.name }, guards, handler))
}

/** What a manager does: `on(manager()).created { name -> ... }`. */
@RtcDsl
public class ManagerTriggers internal constructor(private val owner: Coordination, private val target: ManagerRef, private val guards: List<Guard>) {
    /** Narrows the rule to events for which [guard] holds. */
    public fun where(guard: Guard): ManagerTriggers = ManagerTriggers(owner, target, guards + guard)

    /** When the manager (or one of its slaves) creates a component. */
    public fun created(handler: suspend Reaction.(instanceName: String) -> Unit): Unit = owner.add(
        Rule("$target creates a component", Target.Manager(target), ManagerComponentChanged::class.java, { it.created }, guards) { handler(it.instanceName) },
    )

    /** When a component it hosted is deleted. */
    public fun deleted(handler: suspend Reaction.(instanceName: String) -> Unit): Unit = owner.add(
        Rule("$target deletes a component", Target.Manager(target), ManagerComponentChanged::class.java, { !it.created }, guards) { handler(it.instanceName) },
    )
}

/** Bindings appearing and vanishing in a naming context: `on(context("/localhost/host.host_cxt")).appeared { ... }`. */
@RtcDsl
public class ContextTriggers internal constructor(private val owner: Coordination, private val target: ContextRef, private val guards: List<Guard>) {
    /** Narrows the rule to events for which [guard] holds. */
    public fun where(guard: Guard): ContextTriggers = ContextTriggers(owner, target, guards + guard)

    /** When a binding appears in the context. */
    public fun appeared(handler: suspend Reaction.(Node) -> Unit): Unit = owner.add(
        Rule("$target gains a binding", Target.Context(target), NodeAppeared::class.java, { it.source.path.toString() == RtcPath.parse(target.path).toString() }, guards) { handler(it.child) },
    )

    /** When a binding vanishes from the context. */
    public fun vanished(handler: suspend Reaction.(RtcPath) -> Unit): Unit = owner.add(
        Rule("$target loses a binding", Target.Context(target), NodeVanished::class.java, { it.source.path.toString() == RtcPath.parse(target.path).toString() }, guards) { handler(it.child) },
    )
}
