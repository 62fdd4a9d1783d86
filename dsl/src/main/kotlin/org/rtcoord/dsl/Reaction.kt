package org.rtcoord.dsl

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.TimeoutCancellationException
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.withTimeoutOrNull
import org.rtcoord.ComponentNode
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.LifeCycle
import org.rtcoord.RtcEvent
import org.rtcoord.dsl.internal.ActionJournal
import org.rtcoord.dsl.internal.BestEffort
import org.rtcoord.dsl.internal.Engine
import org.rtcoord.dsl.internal.ScriptCallSite
import org.rtcoord.dsl.internal.Selectors
import org.rtcoord.dsl.internal.Undo
import org.rtcoord.dsl.internal.catchFailure
import org.rtcoord.internal.pollUntil
import org.rtcoord.profile.ProfileDifference
import org.rtcoord.profile.RestoreReport
import org.rtcoord.profile.SystemProfiles

/**
 * What a rule's handler (or a timer) can do. Every action suspends until done, is logged, and fails with an
 * [org.rtcoord.RtcException] that stops the handler: the failure is reported and counted, and the coordinator keeps
 * running. An action that may fail without stopping the handler goes in [attempt]; what to do when the handler stops
 * half way (undo what it did, fall back) goes in [onFailure]:
 * ```
 * on(component("laser0.rtc")).state(ERROR) {
 *     attempt { reset() }                     // a laser that stays broken cannot be reset: go on
 *     onFailure { failure -> failure.undo() } // a switch that fails half way is taken back
 *     component("laser_localise0.rtc").run { disconnectAll(); deactivate() }
 *     manager().create("odo_localise").activate()
 * }
 * ```
 */
@RtcDsl
public class Reaction
internal constructor(
    private val engine: Engine,
    /** The event that fired the rule; null for timers. */
    public val event: RtcEvent?,
) {
    private val source: ComponentRef
        get() =
            (event?.source as? ComponentNode)?.let { engine.reference(it) }
                ?: throw IllegalStateException(
                    "this reaction has no source component (it did not come from a component event)"
                )

    /** A component, by name, path or pattern; with [type], the one component of that type whose name matches. */
    public fun component(name: String = "*", type: String? = null): ComponentRef =
        ComponentRef(Selectors.of(name, type))

    /**
     * Every component [pattern] names now: a glob such as `*_localise?.rtc` (a plain name gets `.rtc`), a name or a
     * path, each component once. For acting on all of them: `components("*_localise?").forEach { it.deactivate() }`.
     * Empty when none matches a glob; a name or path that names nothing fails. With [type], those of that type:
     * `components(type = "laser")`.
     */
    public suspend fun components(pattern: String = "*", type: String? = null): List<ComponentRef> {
        ScriptCallSite.mark()
        return engine.identities.nodes(Selectors.of(pattern, type)).map(engine::reference)
    }

    /** A port, as `component:port`. */
    public fun port(path: String): PortRef = portRef(path)

    /** A manager. */
    public fun manager(name: String = "manager.mgr"): ManagerRef = ManagerRef(name)

    /** Activates the component that fired the rule, within [deadline]; see [ComponentRef.activate]. */
    public suspend fun activate(deadline: Duration? = null): Unit = source.activate(deadline)

    /** Deactivates the component that fired the rule, within [deadline]; see [ComponentRef.deactivate]. */
    public suspend fun deactivate(deadline: Duration? = null): Unit = source.deactivate(deadline)

    /** Resets the component that fired the rule, within [deadline]; see [ComponentRef.reset]. */
    public suspend fun reset(deadline: Duration? = null): Unit = source.reset(deadline)

    /** Makes the component that fired the rule exit. */
    public suspend fun exit(): Unit = source.exit()

    /** Disconnects every port of the component that fired the rule. */
    public suspend fun disconnectAll(): Unit = source.disconnectAll()

    /**
     * Connects out-port [from] to in-port [to] (refs or `component:port` text), with connector [properties]. Undone by
     * removing that connection.
     */
    public suspend fun connect(from: Any, to: Any, properties: Map<String, String> = emptyMap()) {
        val (out, into) = portOf(from) to portOf(to)
        val target = into.port()
        val what = "connect ${out.port().path} to ${target.path}"
        engine.actReversibly(what, out.component, namesItself = true) { node ->
            val made = node.port(out.name).connect(listOf(target), properties)
            val undo: Undo = {
                engine.act("disconnect ${made.name} (${made.id})", out.component, namesItself = true) {
                    it.port(out.name).disconnect(made.id)
                }
            }
            undo
        }
    }

    /** Removes every connection between [a] and [b]. Undone by making them again. */
    public suspend fun disconnect(a: Any, b: Any) {
        val (first, second) = portOf(a) to portOf(b)
        engine.actReversibly(
            "disconnect ${first.port().path} from ${second.port().path}",
            first.component,
            namesItself = true,
        ) { node ->
            val port = node.port(first.name)
            val peer = second.port().path
            val removed = port.connections().filter { connection -> connection.ports.any { it.path == peer } }
            removed.forEach { port.disconnect(it.id) }
            reconnecting(removed, engine)
        }
    }

    /**
     * Runs [block] as a best effort: if it fails, the failure is logged as a warning and the handler goes on. For the
     * actions whose failure must not stop the rest, such as resetting a component whose fault may persist:
     * ```
     * on(component("laser0.rtc")).state(ERROR) {
     *     if (!attempt { reset() }) log("the laser stays broken: switching to odometry without it")
     *     ...
     * }
     * ```
     *
     * A failing action outside [attempt] still stops the handler. Failed actions, best efforts included, are listed by
     * [org.rtcoord.dsl.Coordinator.failedActions].
     *
     * @return whether [block] completed.
     */
    public suspend fun attempt(block: suspend Reaction.() -> Unit): Boolean =
        catchFailure({
            withContext(BestEffort.element) { block() }
            true
        }) { e ->
            engine.log("warning: ${e.message ?: e}; going on (attempt)")
            false
        }

    /**
     * Runs [fallback] if this handler fails after this point, before the failure is reported. It gets the failure, with
     * the actions the handler completed so far ([ReactionFailure.done]), which [ReactionFailure.undo] takes back,
     * newest first:
     * ```
     * onFailure { failure ->
     *     log("switch failed (${failure.cause.message}): back to the laser localiser")
     *     failure.undo()
     *     attempt { component("laser0.rtc").activate() }
     * }
     * ```
     *
     * The fallback's own actions are not undone, and a failure inside it is logged as a warning. Several fallbacks run
     * in the order they were given. Works in rule handlers, timers and escalation handlers; elsewhere (a mode's entry
     * or exit action) it fails at once, naming where it may be used.
     */
    public fun onFailure(fallback: suspend Reaction.(ReactionFailure) -> Unit) {
        checkNotNull(journal) {
            "onFailure works in rule handlers, timers and escalation handlers, not in a mode's entry or exit action"
        }
        fallbacks += fallback
    }

    private var journal: ActionJournal? = null
    private val fallbacks = java.util.concurrent.CopyOnWriteArrayList<suspend Reaction.(ReactionFailure) -> Unit>()

    /**
     * Runs [handler] as this reaction's handler, in a context that holds [journal], where its actions are journaled; if
     * it fails its [onFailure] fallbacks run before the failure goes on to the caller.
     */
    internal suspend fun handle(journal: ActionJournal, handler: suspend Reaction.() -> Unit) {
        this.journal = journal
        catchFailure({ handler() }) { e ->
            val failure = ReactionFailure(e, journal.done) { engine.log(it) }
            for (fallback in fallbacks) {
                catchFailure({ fallback(failure) }) { other ->
                    engine.log("warning: an onFailure block failed: ${other.message ?: other}")
                    e.addSuppressed(other)
                }
            }
            throw e
        }
    }

    /**
     * Restores the RTSProfile [file] (XML or YAML, relative to the script's directory) onto the system, as `rtcoord
     * profile restore` does: connections made (identical ones kept), configuration sets written and the profile's
     * active set activated, execution context rates set; with [createMissing], missing components created through their
     * managers first. Each change is logged. When the profile cannot be applied as a whole (a required component
     * missing, incompatible ports, with [strict] a value outside the constraint its component declares) nothing is
     * changed and the action fails with one line saying why, stopping the handler unless it runs in [attempt]; without
     * [strict] such a value is written, as OpenRTM-aist writes it, and logged as a warning. Restoring again changes
     * nothing. Not undone by [ReactionFailure.undo].
     *
     * ```
     * mode("navigation") { entry { restoreProfile("nav.xml") } }
     * ```
     *
     * @return what was done, kept and found missing.
     */
    public suspend fun restoreProfile(
        file: String,
        createMissing: Boolean = false,
        strict: Boolean = false,
    ): RestoreReport =
        engine.perform("restore profile $file") {
            SystemProfiles(engine.tree).restore(engine.directory.profile(file), createMissing, strict).also { report ->
                report.done.forEach { engine.log("  $it") }
                report.warnings.forEach { engine.log("  warning: $it") }
            }
        }

    /**
     * How the live system differs from the RTSProfile [file] (relative to the script's directory), as `rtcoord profile
     * check` reports it: missing components, states other than [state] (null: states not compared), missing or
     * different connections, configuration and rates. Changes nothing; empty when the system matches:
     * ```
     * every(30.seconds) { checkProfile("nav.xml").takeIf { it.isNotEmpty() }?.let { log("drift: $it") } }
     * ```
     */
    public suspend fun checkProfile(file: String, state: LifeCycle? = LifeCycle.ACTIVE): List<ProfileDifference> =
        engine.perform("check profile $file") {
            SystemProfiles(engine.tree).check(engine.directory.profile(file), state)
        }

    /** Runs [block], failing with [TimedOut] if it takes longer than [timeout]. */
    public suspend fun <T> within(timeout: Duration, block: suspend () -> T): T =
        try {
            withTimeout(timeout) { block() }
        } catch (e: TimeoutCancellationException) {
            throw TimedOut("did not finish within $timeout")
        }

    /**
     * Waits until [condition] holds, reading it every [poll], and fails with [TimedOut] when it still does not after
     * [timeout]: `await(5.seconds) { component("odo_localise0.rtc").state() == ACTIVE }`. A condition that throws ends
     * the wait with its failure. To wait a fixed time, `delay(500.milliseconds)`.
     */
    @OptIn(InternalRtcoordApi::class)
    public suspend fun await(
        timeout: Duration,
        poll: Duration = 100.milliseconds,
        condition: suspend Reaction.() -> Boolean,
    ) {
        ScriptCallSite.mark()
        withTimeoutOrNull(timeout) {
            pollUntil(null, poll) { Unit.takeIf { condition() } }
        } ?: throw TimedOut("the condition did not hold within $timeout")
    }

    /** Writes [message] to the coordinator's log. */
    public fun log(message: String): Unit = engine.log(message)

    /**
     * Writes [message] to the coordinator's log as a warning (`warning: ...`). To stop the handler as failed instead,
     * throw: Kotlin's `error("...")` does, and the failure is logged and counted.
     */
    public fun warn(message: String): Unit = engine.log("warning: $message")
}

/** A [Reaction.within] block that ran out of time. */
public class TimedOut(message: String) : Exception(message)
