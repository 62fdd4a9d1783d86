@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl

import java.nio.file.Path
import java.nio.file.Paths
import kotlin.time.Duration
import org.rtcoord.EventOptions
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.internal.DeclaredGuard
import org.rtcoord.dsl.internal.Selectors
import org.rtcoord.dsl.script.ScriptSource

/**
 * What a coordinator script says: rules (`on(...)`), timers (`every`, `after`), mode machines (`modes(...)`),
 * supervisors (`supervise(...)`), name servers and how to watch. Evaluating a script only declares; a
 * [org.rtcoord.dsl.Coordinator] runs a [Plan] of what was declared, as many times as it is started.
 *
 * @property args the arguments the script was started with.
 * @property host the tree configuration the host application runs the coordinator with.
 * @property directory what the script's relative file names (profiles) are relative to: the script's own directory when
 *   [org.rtcoord.dsl.script.ScriptHost] loads it, else the working directory.
 * @property name what its coordinators are called (a closed one's [org.rtcoord.ClosedException] names it): the script's
 *   file name when [org.rtcoord.dsl.script.ScriptHost] loads it, else the name given.
 */
@RtcDsl
public open class Coordination
@JvmOverloads
constructor(
    public val args: List<String>,
    public val host: TreeConfig,
    public val directory: Path = Paths.get(""),
    public val name: String = "unnamed",
) {
    internal val rules = mutableListOf<Rule<*>>()
    internal val timers = mutableListOf<Timer>()
    internal val supervisions = mutableListOf<Supervision>()
    internal val nameServers = mutableListOf<String>()
    internal val managers = linkedSetOf<String>()
    private val machineList = mutableListOf<ModeMachine>()

    /** The mode machines declared so far. */
    public val machines: List<ModeMachine>
        get() = machineList

    /** How rules watch (push, poll, period, overlap), unless the host overrides it. */
    public var watching: EventOptions = EventOptions()

    /** Name servers to use besides the host's: `host`, `host:port` or `corbaloc:` addresses. */
    public fun nameServers(vararg addresses: String) {
        nameServers += addresses
    }

    /**
     * A component: a full path, a name found on any name server, or (for rules) a glob pattern; with [type], every
     * component of that type whose name matches (`component(type = "laser")`: every laser, those that appear later
     * included), as a glob covers them.
     */
    public fun component(name: String = "*", type: String? = null): ComponentRef =
        ComponentRef(Selectors.of(name, type))

    /** A port, as `component:port`. */
    public fun port(path: String): PortRef = portRef(path)

    /**
     * A manager, by path or by name (on the first name server, in the run's order, that has one so named). A running
     * coordinator watches it from the start: its death and its return are logged, and `on(manager()).died { ... }`
     * reacts to them.
     */
    public fun manager(name: String = "manager.mgr"): ManagerRef = ManagerRef(name).also { managers += name }

    /** A naming context, by path. */
    public fun context(path: String): ContextRef = ContextRef(path)

    /** Rules on a component's events. */
    public fun on(target: ComponentRef): ComponentTriggers = ComponentTriggers(this, target, emptyList())

    /** Rules on a port's events. */
    public fun on(target: PortRef): PortTriggers = PortTriggers(this, target, emptyList())

    /** Rules on a manager's events. */
    public fun on(target: ManagerRef): ManagerTriggers = ManagerTriggers(this, target, emptyList())

    /** Rules on a naming context's events. */
    public fun on(target: ContextRef): ContextTriggers = ContextTriggers(this, target, emptyList())

    /**
     * The log records of the whole system, for `on(logs())`: every record the coordinator's tree receives, whoever sent
     * it.
     */
    public fun logs(): LogsRef = LogsRef

    /** Rules on every log record: `on(logs()).level(ERROR) { record -> ... }`. */
    public fun on(target: LogsRef): LogTriggers = LogTriggers(this, emptyList())

    /** Runs [action] every [period], the first time one period after the start. */
    public fun every(period: Duration, action: suspend Reaction.() -> Unit) {
        timers += Timer("every $period", period, period, action)
    }

    /** Runs [action] once, [delay] after the start. */
    public fun after(delay: Duration, action: suspend Reaction.() -> Unit) {
        timers += Timer("after $delay", delay, null, action)
    }

    /**
     * Runs [action] once when the coordinator starts, once its rules, machines and supervisors watch: `onStart {
     * log("coordinating ${components("*").size} components") }`. A handler like a timer's.
     */
    public fun onStart(action: suspend Reaction.() -> Unit) {
        timers += Timer("on start", Duration.ZERO, null, action, subject = "on start")
    }

    /**
     * Runs [action] when the coordinator stops ([org.rtcoord.dsl.Coordinator.stop]; `rtcoord run` at a signal or the
     * end of `--for`), before its rules stop watching: `onStop { component("odo_localise0.rtc").deactivate() }`. Each
     * such action gets the stop's deadline; its failures are logged and counted like a handler's.
     */
    public fun onStop(action: suspend Reaction.() -> Unit) {
        stopActions += action
    }

    internal val stopActions = mutableListOf<suspend Reaction.() -> Unit>()

    /**
     * Declares the modes of the whole system, a hierarchical state machine named [name] (see [ModeBuilder]):
     * `modes("system") { initial("nominal"); mode("nominal") { ... } }`. The declaration is checked as a whole when
     * [declare] returns and rejected with an [InvalidMachineException] naming every problem, so a machine that cannot
     * run never reaches a coordinator.
     */
    public fun modes(name: String, declare: ModeBuilder.() -> Unit): ModeMachine =
        assemble(ModeBuilder(name, directory).apply(declare), machineList.map { it.name }).also { machineList += it }

    /**
     * Supervises [components], restarting them as [configure] says: `supervise(component("a.rtc"), component("b.rtc"))
     * { strategy = oneForAll; maxRestarts = 3 within 60.seconds }` (see [Supervision]).
     */
    public fun supervise(vararg components: ComponentRef, configure: Supervision.() -> Unit = {}): Supervision =
        Supervision(components.toList()).apply(configure).also { supervisions += it }

    /**
     * What the script declared, one line per rule (with its guards' code, read from the script), timer and supervisor,
     * then each machine's modes, indented by nesting: what `check` shows and tools can draw.
     */
    public val description: List<String>
        get() =
            rules.map { "on ${it.description}${guardsOf(it)}" } +
                dataRules.map { "on ${it.description}" } +
                timers.map { it.description } +
                stopActions.map { "on stop" } +
                supervisions.map { it.description } +
                machineList.flatMap { it.description }

    /**
     * Each guard of [rule] as the script writes it, ` where { ... }`; a guard declared in code, or out of the script's
     * reach, as ` where { ... }` literally.
     */
    private fun guardsOf(rule: Rule<*>): String {
        if (rule.guards.isEmpty()) return ""
        val source = ScriptSource.read(directory.resolve(name))
        return rule.guards.joinToString("") { guard ->
            val code = (guard as? DeclaredGuard)?.line?.let { source?.block(it, "where") }
            " where { ${code ?: "..."} }"
        }
    }

    internal val dataRules = mutableListOf<DataRule>()

    internal fun addData(rule: DataRule) {
        dataRules += rule
    }

    internal fun add(rule: Rule<*>) {
        rules += rule
    }

    /** What was declared so far, frozen: later declarations do not change it. */
    internal fun plan(): Plan =
        Plan(
            rules.toList(),
            dataRules.toList(),
            timers.toList(),
            stopActions.toList(),
            supervisions.toList(),
            machineList.toList(),
            nameServers.toList(),
            managers.toList(),
            watching,
            directory,
        )
}
