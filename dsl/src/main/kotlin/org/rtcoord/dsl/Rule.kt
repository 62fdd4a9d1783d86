package org.rtcoord.dsl

import kotlin.time.Duration
import org.rtcoord.RtcEvent

/** What a rule watches: a component (or pattern), a port, a manager, a naming context or the log records. */
internal sealed class Target {
    /**
     * What a run follows for this target's events when it names components: a name (followed through re-creation) or a
     * pattern (covering every match, as they come).
     */
    open val followedName: String?
        get() = null

    /** What tells two targets apart: equal keys watch the same thing. */
    abstract val key: String

    class Component(val ref: ComponentRef) : Target() {
        override val followedName: String
            get() = ref.selector

        override val key: String
            get() = "component ${ref.selector}"
    }

    class Port(val ref: PortRef) : Target() {
        override val followedName: String
            get() = ref.component.selector

        override val key: String
            get() = "component ${ref.component.selector}"
    }

    class Manager(val ref: ManagerRef) : Target() {
        override val key: String
            get() = "manager ${ref.selector}"
    }

    class Context(val ref: ContextRef) : Target() {
        override val key: String
            get() = "context ${ref.path}"
    }

    /** Every log record the tree's inputs receive, whoever sent it. */
    data object Logs : Target() {
        override val key: String
            get() = "logs"
    }
}

/** A rule: on the events of [pattern] that pass every guard, run [handler]. */
internal class Rule<E : RtcEvent>(
    val pattern: EventPattern<E>,
    val guards: List<suspend Reaction.(RtcEvent) -> Boolean>,
    val handler: suspend Reaction.(E) -> Unit,
) {
    val description: String
        get() = pattern.description

    val target: Target
        get() = pattern.target
}

/** A timer: [action] after [delay], then every [period] if there is one; [subject] names its runs in the log. */
internal class Timer(
    val description: String,
    val delay: Duration,
    val period: Duration?,
    val action: suspend Reaction.() -> Unit,
    val subject: String = "timer $description",
)
