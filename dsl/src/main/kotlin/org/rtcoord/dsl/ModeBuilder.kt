package org.rtcoord.dsl

import java.nio.file.Path
import kotlin.time.Duration
import org.rtcoord.dsl.internal.Selectors

/**
 * Declares a mode (or, in `modes("system") { ... }`, the machine's top): its sub-modes and which is initial, entry and
 * exit actions, the network it needs and its transitions:
 * ```
 * mode("nominal") {
 *     entry { log("nominal") }
 *     network { active("laser0.rtc"); connected("laser0.rtc:laser", "laser_localise0.rtc:laser") }
 *     on(component("laser0.rtc")).state(ERROR) goTo "degraded"
 *     on(failed) goTo "safe"
 *     after(30.seconds) goTo "idle"
 * }
 * ```
 *
 * These functions only declare; the actions (`entry`, `exit`, `goTo { }`, guards) run later, when the coordinator moves
 * between modes.
 */
@RtcDsl
public class ModeBuilder internal constructor(internal val name: String, private val directory: Path) {
    internal val children = mutableListOf<ModeBuilder>()
    internal val initials = mutableListOf<String>()
    internal val entryActions = mutableListOf<suspend Reaction.() -> Unit>()
    internal val exitActions = mutableListOf<suspend Reaction.() -> Unit>()
    internal val triggers = mutableListOf<TransitionTrigger>()
    internal var network: NetworkBuilder? = null
        private set

    /** The reconfiguration of the system for the active modes' network succeeded: `on(done) goTo "running"`. */
    public val done: NetworkOutcome
        get() = NetworkOutcome.DONE

    /** The reconfiguration failed: `on(failed) goTo "safe"`. */
    public val failed: NetworkOutcome
        get() = NetworkOutcome.FAILED

    /**
     * The network of the active modes, once done, broke: a component it requires active entered ERROR, was lost or
     * exited, or a connection it requires was removed: `on(networkBroken) goTo "degraded"`.
     */
    public val networkBroken: NetworkOutcome
        get() = NetworkOutcome.BROKEN

    /** The sub-mode [name] is the one entered when this mode is entered; required when there are sub-modes. */
    public fun initial(name: String) {
        initials += name
    }

    /** Declares sub-mode [name]. */
    public fun mode(name: String, declare: ModeBuilder.() -> Unit = {}) {
        children += ModeBuilder(name, directory).apply(declare)
    }

    /** Runs [action] each time the mode is entered, after its parent's entry actions. */
    public fun entry(action: suspend Reaction.() -> Unit) {
        entryActions += action
    }

    /** Runs [action] each time the mode is left, after its sub-modes' exit actions. */
    public fun exit(action: suspend Reaction.() -> Unit) {
        exitActions += action
    }

    /**
     * Declares the network this mode needs. Entering the mode brings the live system to the network of all active modes
     * (inner ones override outer ones), then raises [done] or [failed].
     */
    public fun network(declare: NetworkBuilder.() -> Unit) {
        (network ?: NetworkBuilder(directory::profile).also { network = it }).declare()
    }

    /**
     * A component, by name or path; for a transition's trigger, a glob, or with [type] every component of that type, as
     * for rules.
     */
    public fun component(name: String = "*", type: String? = null): ComponentRef =
        ComponentRef(Selectors.of(name, type))

    /** A port, as `component:port`. */
    public fun port(path: String): PortRef = portRef(path)

    /** A manager, by name or path. */
    public fun manager(name: String = "manager.mgr"): ManagerRef = ManagerRef(name)

    /** A naming context, by path. */
    public fun context(path: String): ContextRef = ContextRef(path)

    /** Transitions on a component's events. */
    public fun on(target: ComponentRef): ComponentTransitions = ComponentTransitions(this, target)

    /** Transitions on a port's events. */
    public fun on(target: PortRef): PortTransitions = PortTransitions(this, target)

    /** Transitions on a manager's events. */
    public fun on(target: ManagerRef): ManagerTransitions = ManagerTransitions(this, target)

    /** Transitions on a naming context's events. */
    public fun on(target: ContextRef): ContextTransitions = ContextTransitions(this, target)

    /**
     * A transition on the outcome of bringing the system to the active modes' network: `on(done)`, `on(failed)`,
     * `on(networkBroken)`.
     */
    public fun on(outcome: NetworkOutcome): TransitionTrigger = add(Trigger.Network(outcome))

    /** A transition taken once the mode has been active for [delay] (restarting each time it is entered). */
    public fun after(delay: Duration): TransitionTrigger = add(Trigger.Timeout(delay))

    internal fun trigger(pattern: EventPattern<*>): TransitionTrigger = add(Trigger.Event(pattern))

    private fun add(trigger: Trigger): TransitionTrigger = TransitionTrigger(trigger).also { triggers += it }
}
