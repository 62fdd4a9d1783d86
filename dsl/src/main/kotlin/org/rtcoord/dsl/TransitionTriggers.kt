package org.rtcoord.dsl

import org.rtcoord.LifeCycle

/**
 * The events of a component that can trigger a transition: `on(component("laser0.rtc")).state(ERROR) goTo "degraded"`.
 */
@RtcDsl
public class ComponentTransitions
internal constructor(private val mode: ModeBuilder, private val target: ComponentRef) {
    /** When the component enters [state] (in any execution context). */
    public fun state(state: LifeCycle): TransitionTrigger = mode.trigger(EventPatterns.state(target, state))

    /** When its FSM enters [state] (see [ComponentTriggers.fsmState]). */
    public fun fsmState(state: String): TransitionTrigger = mode.trigger(EventPatterns.fsmState(target, state))

    /** On every lifecycle change. */
    public fun stateChanged(): TransitionTrigger = mode.trigger(EventPatterns.stateChanged(target))

    /**
     * When the effective value of configuration parameter [name] changes (set in the active set, or by a set switch).
     */
    public fun configParam(name: String): TransitionTrigger = mode.trigger(EventPatterns.configParam(target, name))

    /** When another configuration set becomes active. */
    public fun configSetActivated(): TransitionTrigger = mode.trigger(EventPatterns.configSetActivated(target))

    /** When the rate of one of its execution contexts changes. */
    public fun rateChanged(): TransitionTrigger = mode.trigger(EventPatterns.rateChanged(target))

    /** When one of its ports gets a connection. */
    public fun connected(): TransitionTrigger = mode.trigger(EventPatterns.connected(target))

    /** When one of its ports loses a connection. */
    public fun disconnected(): TransitionTrigger = mode.trigger(EventPatterns.disconnected(target))

    /** When its heartbeats (or answers to polls) stop. */
    public fun lost(): TransitionTrigger = mode.trigger(EventPatterns.lost(target))

    /** When it cannot be reached at all. */
    public fun zombie(): TransitionTrigger = mode.trigger(EventPatterns.zombie(target))

    /** When it answers again after it was lost. */
    public fun recovered(): TransitionTrigger = mode.trigger(EventPatterns.recovered(target))

    /** When it exits. */
    public fun finalized(): TransitionTrigger = mode.trigger(EventPatterns.finalized(target))
}

/** The events of one port that can trigger a transition: `on(port("gyro0.rtc:gyro")).disconnected() goTo "blind"`. */
@RtcDsl
public class PortTransitions internal constructor(private val mode: ModeBuilder, private val target: PortRef) {
    /** When the port gets a connection. */
    public fun connected(): TransitionTrigger = mode.trigger(EventPatterns.connected(target))

    /** When the port loses a connection. */
    public fun disconnected(): TransitionTrigger = mode.trigger(EventPatterns.disconnected(target))
}

/** What a manager does that can trigger a transition: `on(manager()).created() goTo "starting"`. */
@RtcDsl
public class ManagerTransitions internal constructor(private val mode: ModeBuilder, private val target: ManagerRef) {
    /** When the manager (or one of its slaves) creates a component. */
    public fun created(): TransitionTrigger = mode.trigger(EventPatterns.created(target))

    /** When a component it hosted is deleted. */
    public fun deleted(): TransitionTrigger = mode.trigger(EventPatterns.deleted(target))
}

/** Bindings appearing and vanishing in a naming context, as transition triggers. */
@RtcDsl
public class ContextTransitions internal constructor(private val mode: ModeBuilder, private val target: ContextRef) {
    /** When a binding appears in the context. */
    public fun appeared(): TransitionTrigger = mode.trigger(EventPatterns.appeared(target))

    /** When a binding vanishes from the context. */
    public fun vanished(): TransitionTrigger = mode.trigger(EventPatterns.vanished(target))
}
