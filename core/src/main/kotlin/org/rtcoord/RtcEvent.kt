package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * Something that happened in the live system, as the paper's external callbacks report it: the [source] node, and for
 * changes the old and new values plus what else identifies the change.
 *
 * Events of one source arrive in the order they happened. The same events come from a component's ComponentObserver
 * (push) or from re-reading it (poll); see [EventOptions.mode].
 *
 * Events are plain classes, so that they can gain fields without breaking compiled callers (no `componentN`, no
 * `copy`); equal when they are of one type and their constructors took equal values.
 */
public sealed class RtcEvent : ValueObject() {
    /** The node the event is about. */
    public abstract val source: Node

    /** When the tree noticed it, in milliseconds since the epoch. */
    public val noticedAt: Long = System.currentTimeMillis()

    /**
     * Where the event stands in the tree's history: every event the tree publishes gets the next number, and a
     * [SystemSnapshot] with [SystemSnapshot.sequence] N holds every event up to N. 0 for an event the tree made but has
     * not published.
     */
    public var sequence: Long = 0L
        @JvmSynthetic internal set

    /** The source's path. */
    public val path: RtcPath
        get() = source.path
}

/** A component's lifecycle state in execution context [handle] went from [old] to [new]. */
public class StateChanged(
    override val source: ComponentNode,
    public val handle: Int,
    public val old: LifeCycle,
    public val new: LifeCycle,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "handle" to handle, "old" to old, "new" to new)
}

/** A component finalised (exited) and is gone. */
public class ComponentFinalized(override val source: ComponentNode) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source)
}

/**
 * An FSM component's state machine entered state [new], as its FSM4RTC observer told it (StaticFSM's `<state>
 * POST_ONENTRY`); [old] is the state it entered before, null when none was told since the tree began watching. A
 * transition into a nested state enters each state on the way down, in order (`Operational`, then `Idle`), with one
 * event each; leaving a state is no event.
 */
public class FsmStateChanged(override val source: ComponentNode, public val old: String?, public val new: String) :
    RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "old" to old, "new" to new)
}

/** Port [port] of the component got connection [connector]. */
public class PortConnected(
    override val source: ComponentNode,
    public val port: String,
    public val connector: ConnectorSnapshot,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "port" to port, "connector" to connector)
}

/** Port [port] of the component lost connection [connector]. */
public class PortDisconnected(
    override val source: ComponentNode,
    public val port: String,
    public val connector: ConnectorSnapshot,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "port" to port, "connector" to connector)
}

/**
 * Port [port] of the component sent ([outgoing]) or received data: OpenRTM-aist's `SEND:` and `RECEIVE:` observer
 * hints, which a component sends at most once per [EventOptions.trafficInterval] per port. Only a component's observer
 * tells this (a read cannot), so polled components send none. Data hints are many: only registrations that name this
 * type (not a supertype such as [RtcEvent]) receive them.
 */
public class PortTraffic(override val source: ComponentNode, public val port: String, public val outgoing: Boolean) :
    RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "port" to port, "outgoing" to outgoing)
}

/** Parameter [name] of configuration set [set] changed from [old] to [new] (null: absent). */
public class ParameterChanged(
    override val source: ComponentNode,
    public val set: String,
    public val name: String,
    public val old: String?,
    public val new: String?,
) : RtcEvent() {
    override fun fields(): ValueFields =
        ValueFields("source" to source, "set" to set, "name" to name, "old" to old, "new" to new)
}

/**
 * The active configuration set changed from [old] to [new]; null is none active (after a set was written, added or
 * removed).
 */
public class ConfigurationSetActivated(
    override val source: ComponentNode,
    public val old: String?,
    public val new: String?,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "old" to old, "new" to new)
}

/** Configuration set [id] was added. */
public class ConfigurationSetAdded(override val source: ComponentNode, public val id: String) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "id" to id)
}

/** Configuration set [id] was removed. */
public class ConfigurationSetRemoved(override val source: ComponentNode, public val id: String) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "id" to id)
}

/** The rate of execution context [handle] changed from [old] to [new] Hz. */
public class ContextRateChanged(
    override val source: ComponentNode,
    public val handle: Int,
    public val old: Double,
    public val new: Double,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "handle" to handle, "old" to old, "new" to new)
}

/** Execution context [handle] started ([running] true) or stopped. */
public class ContextRunningChanged(
    override val source: ComponentNode,
    public val handle: Int,
    @get:JvmName("isRunning") public val running: Boolean,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "handle" to handle, "running" to running)
}

/** The component joined ([attached] true) or left execution context [handle]. */
public class ContextAttachmentChanged(
    override val source: ComponentNode,
    public val handle: Int,
    @get:JvmName("isAttached") public val attached: Boolean,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "handle" to handle, "attached" to attached)
}

/** Manager [source] created ([created] true) or deleted component [instanceName]. */
public class ManagerComponentChanged(
    override val source: ManagerNode,
    public val instanceName: String,
    public val created: Boolean,
) : RtcEvent() {
    override fun fields(): ValueFields =
        ValueFields("source" to source, "instanceName" to instanceName, "created" to created)
}

/**
 * A binding [child] appeared under [source]. For a component, [snapshot] is what the tree read of it when it appeared:
 * what happened to it between its creation and its discovery (its state, its connections).
 */
public class NodeAppeared(
    override val source: DirectoryNode,
    public val child: Node,
    public val snapshot: ComponentSnapshot? = null,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "child" to child, "snapshot" to snapshot)
}

/** The binding at [child] vanished from [source]. */
public class NodeVanished(override val source: DirectoryNode, public val child: RtcPath) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "child" to child)
}

/** No heartbeat (push) or no answer (poll) for [silentMillis]: the component is presumed dead. */
public class HeartbeatLost(override val source: ComponentNode, public val silentMillis: Long) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "silentMillis" to silentMillis)
}

/** The component could not be reached at all: [cause]. */
public class BecameZombie(override val source: ComponentNode, public val cause: RtcException) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "cause" to cause)
}

/** A component presumed dead answers again. */
public class Recovered(override val source: ComponentNode) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source)
}

/** The tree watches the component by [new] from now on; [old] is null when it has just started watching it. */
public class WatchMethodChanged(
    override val source: ComponentNode,
    public val old: WatchMethod?,
    public val new: WatchMethod,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "old" to old, "new" to new)
}

/**
 * Manager [source] stopped answering: its process died or hangs. [components] are those its last listing showed; they
 * went silent with it, and each reports its own [HeartbeatLost] and [BecameZombie].
 */
public class ManagerDied(
    override val source: ManagerNode,
    public val components: List<ComponentNode>,
    public val cause: RtcException,
) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "components" to components, "cause" to cause)
}

/** Manager [source], presumed dead, answers again. */
public class ManagerReturned(override val source: ManagerNode) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source)
}

/**
 * Name server [source] stopped answering: [cause]. Until [NameServerReturned], nothing is known of what is registered
 * on it; the components themselves may still run.
 */
public class NameServerLost(override val source: NameServerNode, public val cause: RtcException) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "cause" to cause)
}

/** Name server [source], lost, answers again after [downMillis] milliseconds. */
public class NameServerReturned(override val source: NameServerNode, public val downMillis: Long) : RtcEvent() {
    override fun fields(): ValueFields = ValueFields("source" to source, "downMillis" to downMillis)
}

/**
 * A log record a component's process sent to one of the tree's log inputs ([RtcTree.listenForLogs]), as OpenRTM-aist
 * 2.x sends them to Fluentd (OpenRTM-aist-Python's FluentLogger, C++'s `fluentbit_stream`).
 *
 * [source] is whom the tree found it to be from: the component whose instance name the record's [logger] is, else the
 * only component of the manager named [manager], else that manager; a record none of these matches (a process the tree
 * has not listed) comes from the tree's root, and [host] and [pid] say where it came from.
 */
public class LogRecord(
    override val source: Node,
    /** When the sender stamped it, in milliseconds since the epoch. */
    public val loggedAt: Long,
    public val level: LogLevel,
    /** The logger's name as sent: OpenRTM-aist's C++ names a component's logger by its instance name. */
    public val logger: String,
    public val message: String,
    /** The sender's process id; null when it did not say. */
    public val pid: Long?,
    /** The sender's host name; null when it did not say. */
    public val host: String?,
    /** The instance name of the sender's manager (`manager.instance_name`); null when it did not say. */
    public val manager: String?,
    /** The Fluentd tag it came with (`rtclog` by default in OpenRTM-aist's C++). */
    public val tag: String,
) : RtcEvent() {
    override fun fields(): ValueFields =
        ValueFields(
            "source" to source,
            "loggedAt" to loggedAt,
            "level" to level,
            "logger" to logger,
            "message" to message,
            "pid" to pid,
            "host" to host,
            "manager" to manager,
            "tag" to tag,
        )
}
