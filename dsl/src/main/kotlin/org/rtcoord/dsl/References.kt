package org.rtcoord.dsl

import kotlin.time.Duration
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.Connection
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerNode
import org.rtcoord.Port
import org.rtcoord.PortSnapshot
import org.rtcoord.RtcPath
import org.rtcoord.TransitionOutcome
import org.rtcoord.dsl.internal.Engine
import org.rtcoord.dsl.internal.Selectors
import org.rtcoord.dsl.internal.Undo

/**
 * A component named in a script: a full path, a name searched on every name server, or a glob pattern
 * (`*_localise?.rtc`) or a type (`component(type = "laser")`, selector `* type=laser`), rules only. A plain selector:
 * the running coordinator resolves it when it is used, and again after the component is re-created, so it never pins
 * one CORBA reference for life. Its actions run in a running coordinator's handlers; they wait for their effect and log
 * what they do.
 */
@RtcDsl
public class ComponentRef
internal constructor(
    /** What the script wrote. */
    public val selector: String
) {
    /** Whether the selector is a pattern that may match several components: a glob, or a type. */
    public val isPattern: Boolean
        get() = Selectors.isPattern(selector)

    internal suspend fun node(): ComponentNode = Engine.current().component(selector)

    /** The component's path, as resolved now. */
    public suspend fun path(): RtcPath = node().path

    /** Its state in its default execution context, read now (from the component answering to the name now). */
    public suspend fun state(): LifeCycle = Engine.current().withComponent(selector) { it.state() }

    /**
     * What was last read of it: its profile, ports with their connectors, execution contexts with its state in each.
     */
    public suspend fun snapshot(): ComponentSnapshot = node().snapshot()

    /**
     * Its configuration: every set by id with its parameters, and which set is active ([ConfigurationSnapshot.value]
     * reads a parameter in force); read the first time, kept up to date after.
     */
    public suspend fun configuration(): ConfigurationSnapshot =
        Engine.current().withComponent(selector) { it.configuration() }

    /**
     * Activates it and waits until it is ACTIVE, within [deadline] (the tree's call timeout by default); one that gets
     * there after its context answered `RTC_ERROR` (its transition timeout passed first) is logged as slow, not failed.
     * Undone by a deactivation.
     */
    public suspend fun activate(deadline: Duration? = null): Unit =
        Engine.current().let { engine ->
            engine.actReversibly("activate", this) {
                engine.noteSlow(it.activate(deadline = deadline));
                { deactivate() }
            }
        }

    /**
     * Deactivates it and waits until it is INACTIVE, within [deadline], slow ones as [activate]. Undone by an
     * activation.
     */
    public suspend fun deactivate(deadline: Duration? = null): Unit =
        Engine.current().let { engine ->
            engine.actReversibly("deactivate", this) {
                engine.noteSlow(it.deactivate(deadline = deadline));
                { activate() }
            }
        }

    /**
     * Resets it from ERROR and waits until it is INACTIVE, within [deadline], slow ones as [activate]. A reset whose
     * `on_reset` fails is told from a slow one only at [deadline] (the component stays in ERROR either way, and says
     * nothing): a script that goes on without a component it cannot reset chooses how long a reset may take, `attempt {
     * reset(deadline = 1.seconds) }`.
     */
    public suspend fun reset(deadline: Duration? = null): Unit =
        Engine.current().let { engine -> engine.act("reset", this) { engine.noteSlow(it.reset(deadline = deadline)) } }

    /** Logs a transition that got there after its context had answered it did not. */
    private fun Engine.noteSlow(outcome: TransitionOutcome) {
        if (outcome.slow) log("  slow: $outcome")
    }

    /** Makes it exit. */
    public suspend fun exit(): Unit = Engine.current().act("exit", this) { it.exit() }

    /** Disconnects every connection of every port. Undone by making the same connections again. */
    public suspend fun disconnectAll() {
        val engine = Engine.current()
        engine.actReversibly("disconnect all", this) { node ->
            val connections = node.snapshot().ports.flatMap { node.port(it.name).connections() }.distinctBy { it.id }
            node.disconnectAll()
            reconnecting(connections, engine)
        }
    }

    /**
     * Sets parameters of its active configuration set (or of `inSet(...)`'s set), all in one change: `configure {
     * set("gain", "2.0") }`. An unknown parameter or a value the component refuses changes none. A value outside the
     * constraint the component declares is written, as OpenRTM-aist writes it, and logged as a warning.
     */
    public suspend fun configure(changes: ConfigurationChanges.() -> Unit) {
        val requested = ConfigurationChanges().apply(changes)
        val engine = Engine.current()
        engine.act("configure ${requested.describe()}", this) { node ->
            node.setParameters(requested.values, requested.set).forEach { engine.log("  warning: ${node.path}: $it") }
        }
    }

    /** Makes configuration set [id] the active one. */
    public suspend fun activateConfigSet(id: String): Unit =
        Engine.current().act("activate configuration set $id", this) { it.activateConfigurationSet(id) }

    /** Its port [name]. */
    public fun port(name: String): PortRef = PortRef(this, name)

    override fun toString(): String = selector
}

/** A port of a component: `component("gyro0.rtc").port("gyro")`, or `port("gyro0.rtc:gyro")`. */
@RtcDsl
public class PortRef internal constructor(public val component: ComponentRef, public val name: String) {
    internal suspend fun port(): Port = component.node().port(name)

    /** What was last read of it: its kind, data type, properties and connectors (ids, names, properties). */
    public suspend fun snapshot(): PortSnapshot = port().snapshot()

    /**
     * Its connections, read now, each with both its ends ([Connection.ports]: OpenRTM's full name and, where known, the
     * path).
     */
    public suspend fun connections(): List<Connection> = port().connections()

    /**
     * The ports at the far end of its connections, read now, each once: what a connector's snapshot alone does not say.
     * `port("laser0.rtc:laser").peers()` gives `[laser_localise0.rtc:laser]`-like refs, named by path where the tree
     * knows the far component, else by OpenRTM's `instance.port`.
     */
    public suspend fun peers(): List<PortRef> {
        val here = port()
        return here
            .connections()
            .flatMap { it.ports }
            .filter { it.path != here.path }
            .map { end ->
                end.path?.let { portRef(it.toString()) }
                    ?: PortRef(
                        ComponentRef(end.fullName.substringBeforeLast('.')),
                        end.fullName.substringAfterLast('.'),
                    )
            }
            .distinctBy { it.toString() }
    }

    /** Disconnects every connection of this port. Undone by making the same connections again. */
    public suspend fun disconnectAll() {
        val engine = Engine.current()
        engine.actReversibly("disconnect all of $this", component) { node ->
            val port = node.port(name)
            val connections = port.connections()
            port.disconnectAll()
            reconnecting(connections, engine)
        }
    }

    override fun toString(): String = "${component.selector}:$name"
}

/** A manager named in a script (`manager.mgr` by default, searched like a component name or a full path). */
@RtcDsl
public class ManagerRef internal constructor(public val selector: String) {
    /** Creates a component of [type] (named [name], or as the manager names it) and returns it. */
    public suspend fun create(type: String, name: String? = null): ComponentRef =
        Engine.current().create(this, type, name)

    /** Deletes component [instanceName] through the manager that hosts it. */
    public suspend fun delete(instanceName: String): Unit = Engine.current().delete(this, instanceName)

    /** Whether it names [manager] itself (by path, or by name), not one of its slaves. */
    internal fun names(manager: ManagerNode): Boolean =
        if (selector.startsWith("/")) manager.path == RtcPath(selector) else manager.name == selector

    override fun toString(): String = selector
}

/** A naming context watched for bindings appearing and vanishing. */
@RtcDsl
public class ContextRef internal constructor(public val path: String) {
    override fun toString(): String = path
}

/** Every log record the tree receives, whoever sent it ([Coordination.logs]). */
public object LogsRef {
    override fun toString(): String = "logs()"
}

/** The parameter changes of [ComponentRef.configure]. */
@RtcDsl
public class ConfigurationChanges internal constructor() {
    internal val values = linkedMapOf<String, String>()
    internal var set: String? = null
        private set

    /** Sets parameter [name] to [value]. */
    public fun set(name: String, value: String) {
        values[name] = value
    }

    /** Changes configuration set [id] instead of the active one. */
    public fun inSet(id: String) {
        set = id
    }

    internal fun describe(): String =
        values.entries.joinToString { "${it.key}=${it.value}" } + (set?.let { " in $it" } ?: "")
}

/** The port [path] names, as `component:port`. */
internal fun portRef(path: String): PortRef {
    val split = path.lastIndexOf(':')
    require(split > 0 && split < path.length - 1) { "not a port: '$path' (write component:port)" }
    return PortRef(ComponentRef(path.substring(0, split)), path.substring(split + 1))
}

/** [port] as a port: a [PortRef] or `component:port` text. */
internal fun portOf(port: Any): PortRef =
    when (port) {
        is PortRef -> port
        is String -> portRef(port)
        else -> throw IllegalArgumentException("not a port: $port (a port(...) or \"component:port\")")
    }

/** How to undo the removal of [connections]: make each again. */
internal fun reconnecting(connections: List<Connection>, engine: Engine): Undo = {
    connections.forEach { engine.reconnect(it) }
}
