package org.rtcoord.dsl

import org.rtcoord.RtcEvent
import kotlin.time.Duration

/** What a rule watches: a component (or pattern), a port, a manager or a naming context. */
internal sealed class Target {
    class Component(val ref: ComponentRef) : Target()
    class Port(val ref: PortRef) : Target()
    class Manager(val ref: ManagerRef) : Target()
    class Context(val ref: ContextRef) : Target()
}

/** A rule: on the events of [pattern] that pass every guard, run [handler]. */
internal class Rule<E : RtcEvent>(
    val pattern: EventPattern<E>,
    val guards: List<suspend Reaction.(RtcEvent) -> Boolean>,
    val handler: suspend Reaction.(E) -> Unit,
) {
    val description: String get() = pattern.description
    val target: Target get() = pattern.target
}

/** A timer: [action] after [delay], then every [period] if there is one. */
internal class Timer(val description: String, val delay: Duration, val period: Duration?, val action: suspend Reaction.() -> Unit)
