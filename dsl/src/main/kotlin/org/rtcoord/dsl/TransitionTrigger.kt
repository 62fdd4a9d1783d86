package org.rtcoord.dsl

import kotlin.time.Duration

/**
 * The outcome of bringing the live system to a mode's network, and what happens to it after: `on(done) goTo "running"`,
 * `on(failed) goTo "safe"`, `on(networkBroken) goTo "degraded"`.
 */
public enum class NetworkOutcome(private val text: String) {
    /** The live system was read back and matches the network the active modes declare. */
    DONE("done"),

    /** A step failed, missed its deadline, or the result read back differs; the reason names the step and object. */
    FAILED("failed"),

    /**
     * After [DONE], the network broke: a component it requires active entered ERROR, was lost, became unreachable or
     * exited, or a connection it requires was removed. Raised once per network brought about; each breach is logged.
     */
    BROKEN("networkBroken");

    /** The name a script writes. */
    override fun toString(): String = text
}

/** What makes a transition go: an event of the live system, the outcome of a reconfiguration, or time in a mode. */
internal sealed class Trigger {
    abstract val description: String

    /** How the script declared it: `on laser0.rtc enters ERROR`, `on done`, `after 5s`. */
    val declaration: String
        get() = if (this is Timeout) description else "on $description"

    class Event(val pattern: EventPattern<*>) : Trigger() {
        override val description: String
            get() = pattern.description
    }

    class Network(val outcome: NetworkOutcome) : Trigger() {
        override val description: String
            get() = outcome.toString()
    }

    class Timeout(val delay: Duration) : Trigger() {
        override val description: String
            get() = "after $delay"
    }
}

/**
 * A transition being declared: its trigger, narrowed by guards, completed by [goTo]:
 * `on(component("laser0.rtc")).state(ERROR).where { ... } goTo "degraded"`. A trigger without a [goTo] is an error when
 * the machine is checked.
 */
@RtcDsl
public class TransitionTrigger internal constructor(internal val trigger: Trigger) {
    internal val guards = mutableListOf<suspend Reaction.() -> Boolean>()
    internal val targets = mutableListOf<String>()
    internal var action: (suspend Reaction.() -> Unit)? = null
        private set

    /**
     * Takes the transition only when [guard] holds; its [Reaction.event] is the triggering event (null for `done`,
     * `failed` and `after`). Guards are checked in order, deepest mode first.
     */
    public fun where(guard: suspend Reaction.() -> Boolean): TransitionTrigger = apply { guards += guard }

    /** Goes to the mode named [mode] (a mode with sub-modes is entered through its initial ones). */
    public infix fun goTo(mode: String) {
        targets += mode
    }

    /** Goes to the mode named [mode], running [action] after the exits and before the entries. */
    public fun goTo(mode: String, action: suspend Reaction.() -> Unit) {
        targets += mode
        this.action = action
    }
}
