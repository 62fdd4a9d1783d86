package org.rtcoord.dsl

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * A supervisor, as a script declares it with `supervise(component("a.rtc"), component("b.rtc")) { ... }`: the
 * components in their declared order, the [strategy], the restart intensity ([maxRestarts]), the [backoff] and the
 * [restart] type. A [org.rtcoord.dsl.Coordinator] runs it:
 *
 * - a component that enters ERROR is reset and activated again;
 * - one that is lost (no heartbeat, unreachable) is reset and activated if it still answers, else re-created through
 *   the manager that hosted it (or that manager's master) with the same type and name, its connections made again and
 *   its active configuration set restored, then activated;
 * - one that exits is re-created the same way if it is [permanent];
 * - the [strategy] decides which of the others are restarted with it: stopped in reverse declared order before, started
 *   in declared order after;
 * - a failure beyond [maxRestarts] escalates: [onEscalation] handlers run and the supervisor stops.
 *
 * A component whose registration vanishes is noticed by its own events: it exited, or it stopped answering. A component
 * that still runs but was unbound from naming has not failed. Connections are recorded when the supervisor starts and
 * as they are made; one removed while all its supervised components run normally is removed on purpose and not made
 * again.
 *
 * Every step goes to the coordinator's log; a step that fails is logged with the object it concerned.
 */
@RtcDsl
public class Supervision internal constructor(internal val children: List<ComponentRef>) {
    init {
        require(children.isNotEmpty()) { "supervise needs at least one component" }
        children
            .firstOrNull { it.isPattern }
            ?.let { throw IllegalArgumentException("cannot supervise '$it': it is a pattern; name each component") }
        val twice = children.groupBy { it.selector }.filterValues { it.size > 1 }.keys
        require(twice.isEmpty()) { "cannot supervise ${twice.joinToString()} twice in one supervisor" }
    }

    internal val restartOverrides = mutableMapOf<ComponentRef, RestartType>()
    internal val escalationHandlers = mutableListOf<suspend Reaction.(Escalation) -> Unit>()

    /** Which components restart with a failed one; [oneForOne] by default. */
    public var strategy: Strategy = Strategy.ONE_FOR_ONE

    /** How many restarts within how long before escalating: `maxRestarts = 3 within 60.seconds` (the default). */
    public var maxRestarts: RestartIntensity = RestartIntensity(3, 60.seconds)

    /** The wait before consecutive restarts of one component; [immediately] by default. */
    public var backoff: Backoff = Backoff.NONE

    /** When the components are restarted, unless [child] says otherwise; [permanent] by default. */
    public var restart: RestartType = RestartType.PERMANENT

    /** Restart only the failed component. */
    public val oneForOne: Strategy
        get() = Strategy.ONE_FOR_ONE

    /** Restart every component. */
    public val oneForAll: Strategy
        get() = Strategy.ONE_FOR_ALL

    /** Restart the failed component and those declared after it. */
    public val restForOne: Strategy
        get() = Strategy.REST_FOR_ONE

    /** Restarted after failures and after exits. */
    public val permanent: RestartType
        get() = RestartType.PERMANENT

    /** Restarted after failures only. */
    public val transient: RestartType
        get() = RestartType.TRANSIENT

    /** Never restarted. */
    public val temporary: RestartType
        get() = RestartType.TEMPORARY

    /** No wait between restarts. */
    public val immediately: Backoff
        get() = Backoff.NONE

    /** [maxRestarts] restarts within [period]: `3 within 60.seconds`. */
    public infix fun Int.within(period: Duration): RestartIntensity = RestartIntensity(this, period)

    /** Waits [initial] before a restart, twice as long before each consecutive one, at most [max]. */
    public fun exponential(initial: Duration, max: Duration): Backoff = Backoff.exponential(initial, max)

    /** Gives the supervised component [component] its own [restart] type: `child(logger, restart = temporary)`. */
    public fun child(component: ComponentRef, restart: RestartType) {
        require(component in children) {
            "'$component' is not supervised here (supervised: ${children.joinToString()})"
        }
        restartOverrides[component] = restart
    }

    /** [child] by the name or path the component was given in `supervise(...)`. */
    public fun child(name: String, restart: RestartType) {
        child(
            children.firstOrNull { it.selector == name || it.selector == "$name.rtc" || "${it.selector}.rtc" == name }
                ?: throw IllegalArgumentException(
                    "'$name' is not supervised here (supervised: ${children.joinToString()})"
                ),
            restart,
        )
    }

    /** Runs [handler] when the supervisor gives up; it may act on the system like a rule's handler. */
    public fun onEscalation(handler: suspend Reaction.(Escalation) -> Unit) {
        escalationHandlers += handler
    }

    internal fun restartOf(component: ComponentRef): RestartType = restartOverrides[component] ?: restart

    /** What the supervisor is called in the log: its components' names. */
    internal val name: String
        get() = "supervisor(${children.joinToString()})"

    /** One line: what `check` shows. */
    public val description: String
        get() =
            "supervise ${children.joinToString()}: $strategy, at most $maxRestarts, back-off $backoff, $restart" +
                restartOverrides.entries.joinToString("") { (child, type) -> ", $child $type" }
}
