package org.rtcoord

/**
 * Something that happened in the live system, as the paper's external callbacks report it: the
 * [source] node, and for changes the old and new values plus what else identifies the change.
 *
 * Events of one source arrive in the order they happened. The same events come from a component's
 * ComponentObserver (push) or from re-reading it (poll); see [EventOptions.mode].
 */
public sealed class RtcEvent {
    /** The node the event is about. */
    public abstract val source: Node

    /** When the tree noticed it, in milliseconds since the epoch. */
    public val noticedAt: Long = System.currentTimeMillis()

    /**
     * Where the event stands in the tree's history: every event the tree publishes gets the next number,
     * and a [SystemSnapshot] with [SystemSnapshot.sequence] N holds every event up to N. 0 for an event the
     * tree made but has not published.
     */
    public var sequence: Long = 0L
        internal set

    /** The source's path. */
    public val path: RtcPath get() = source.path
}

/** A component's lifecycle state in execution context [handle] went from [old] to [new]. */
public data class StateChanged(override val source: ComponentNode, val handle: Int, val old: LifeCycle, val new: LifeCycle) : RtcEvent()

/** A component finalised (exited) and is gone. */
public data class ComponentFinalized(override val source: ComponentNode) : RtcEvent()

/** Port [port] of the component got connection [connector]. */
public data class PortConnected(override val source: ComponentNode, val port: String, val connector: ConnectorSnapshot) : RtcEvent()

/** Port [port] of the component lost connection [connector]. */
public data class PortDisconnected(override val source: ComponentNode, val port: String, val connector: ConnectorSnapshot) : RtcEvent()

/**
 * Port [port] of the component sent ([outgoing]) or received data: OpenRTM-aist's `SEND:` and `RECEIVE:`
 * observer hints, which a component sends at most once per [EventOptions.trafficInterval] per port.
 * Only a component's observer tells this (a read cannot), so polled components send none. Data hints are
 * many: only registrations that name this type (not a supertype such as [RtcEvent]) receive them.
 */
public data class PortTraffic(override val source: ComponentNode, val port: String, val outgoing: Boolean) : RtcEvent()

/** Parameter [name] of configuration set [set] changed from [old] to [new] (null: absent). */
public data class ParameterChanged(override val source: ComponentNode, val set: String, val name: String, val old: String?, val new: String?) : RtcEvent()

/** The active configuration set changed from [old] to [new]; null is none active (after a set was written, added or removed). */
public data class ConfigurationSetActivated(override val source: ComponentNode, val old: String?, val new: String?) : RtcEvent()

/** Configuration set [id] was added. */
public data class ConfigurationSetAdded(override val source: ComponentNode, val id: String) : RtcEvent()

/** Configuration set [id] was removed. */
public data class ConfigurationSetRemoved(override val source: ComponentNode, val id: String) : RtcEvent()

/** The rate of execution context [handle] changed from [old] to [new] Hz. */
public data class ContextRateChanged(override val source: ComponentNode, val handle: Int, val old: Double, val new: Double) : RtcEvent()

/** Execution context [handle] started ([running] true) or stopped. */
public data class ContextRunningChanged(override val source: ComponentNode, val handle: Int, @get:JvmName("isRunning") val running: Boolean) : RtcEvent()

/** The component joined ([attached] true) or left execution context [handle]. */
public data class ContextAttachmentChanged(override val source: ComponentNode, val handle: Int, @get:JvmName("isAttached") val attached: Boolean) : RtcEvent()

/** Manager [source] created ([created] true) or deleted component [instanceName]. */
public data class ManagerComponentChanged(override val source: ManagerNode, val instanceName: String, val created: Boolean) : RtcEvent()

/**
 * A binding [child] appeared under [source]. For a component, [snapshot] is what the tree read of it when
 * it appeared: what happened to it between its creation and its discovery (its state, its connections).
 */
public data class NodeAppeared(override val source: DirectoryNode, val child: Node, val snapshot: ComponentSnapshot? = null) : RtcEvent()

/** The binding at [child] vanished from [source]. */
public data class NodeVanished(override val source: DirectoryNode, val child: RtcPath) : RtcEvent()

/** No heartbeat (push) or no answer (poll) for [silentMillis]: the component is presumed dead. */
public data class HeartbeatLost(override val source: ComponentNode, val silentMillis: Long) : RtcEvent()

/** The component could not be reached at all: [cause]. */
public data class BecameZombie(override val source: ComponentNode, val cause: RtcException) : RtcEvent()

/** A component presumed dead answers again. */
public data class Recovered(override val source: ComponentNode) : RtcEvent()

/** The tree watches the component by [new] from now on; [old] is null when it has just started watching it. */
public data class WatchMethodChanged(override val source: ComponentNode, val old: WatchMethod?, val new: WatchMethod) : RtcEvent()

/**
 * Manager [source] stopped answering: its process died or hangs. [components] are those its last listing
 * showed; they went silent with it, and each reports its own [HeartbeatLost] and [BecameZombie].
 */
public data class ManagerDied(override val source: ManagerNode, val components: List<ComponentNode>, val cause: RtcException) : RtcEvent()

/** Manager [source], presumed dead, answers again. */
public data class ManagerReturned(override val source: ManagerNode) : RtcEvent()

/**
 * Name server [source] stopped answering: [cause]. Until [NameServerReturned], nothing is known of what is
 * registered on it; the components themselves may still run.
 */
public data class NameServerLost(override val source: NameServerNode, val cause: RtcException) : RtcEvent()

/** Name server [source], lost, answers again after [downMillis] milliseconds. */
public data class NameServerReturned(override val source: NameServerNode, val downMillis: Long) : RtcEvent()
