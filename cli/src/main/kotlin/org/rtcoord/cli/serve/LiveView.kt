package org.rtcoord.cli.serve

import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableSharedFlow
import kotlinx.coroutines.flow.SharedFlow
import kotlinx.coroutines.flow.asSharedFlow
import kotlinx.coroutines.launch
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ConfigurationSetAdded
import org.rtcoord.ConfigurationSetRemoved
import org.rtcoord.ContextAttachmentChanged
import org.rtcoord.ContextRateChanged
import org.rtcoord.ContextRunningChanged
import org.rtcoord.EventOptions
import org.rtcoord.FsmStateChanged
import org.rtcoord.HeartbeatLost
import org.rtcoord.ManagerComponentChanged
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerReturned
import org.rtcoord.Node
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.PortTraffic
import org.rtcoord.Recovered
import org.rtcoord.RootNode
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import org.rtcoord.Subscription
import org.rtcoord.SystemSnapshot
import org.rtcoord.WatchMethodChanged
import org.rtcoord.cli.discover
import org.rtcoord.cli.toJson
import org.rtcoord.cli.what
import org.rtcoord.dsl.Coordinator
import java.time.Instant
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration.Companion.milliseconds

/**
 * The live state the page shows, derived from the tree's events below [top] and, when there is one,
 * the [coordinator]'s observable state: a snapshot for a page that (re)connects, then [updates]:
 * `event` for each event and log line, `network` when the network's shape may have changed,
 * `coordinator` when the coordinator's state did.
 */
internal class LiveView(
    private val tree: RtcTree,
    private val top: Node,
    private val coordinator: Coordinator?,
    private val options: EventOptions,
    /** Whether the page may operate components. */
    val operable: Boolean,
) : AutoCloseable {
    /** One message to every connected page: its SSE event name and JSON data. */
    data class Update(val kind: String, val json: String)

    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default + CoroutineName("live-view"))
    private val broadcast = MutableSharedFlow<Update>(extraBufferCapacity = BUFFERED, onBufferOverflow = BufferOverflow.DROP_OLDEST)
    private val recent = ArrayDeque<Map<String, Any?>>()
    private val sequence = AtomicLong()
    private val reshaped = Channel<Unit>(Channel.CONFLATED)
    private val subscriptions = CopyOnWriteArrayList<Subscription>()
    @Volatile private var network: Map<String, Any?> = emptyMap()
    @Volatile private var coordinatorState: Map<String, Any?>? = null

    /** What happens after a page took its [snapshot]. */
    val updates: SharedFlow<Update> = broadcast.asSharedFlow()

    /** Reads the system, subscribes to its events and starts following the coordinator. */
    suspend fun start() {
        discover(top, null)
        val watched = if (top is RootNode) tree.nameServers else listOf(top)
        subscriptions += tree.follow(watched, setOf(RtcEvent::class.java), options, start = { model -> network = NetworkView(top, model).toJson() }) { publish(it) }
        scope.launch {
            for (signal in reshaped) {
                // Changes come in bursts (a component appears with its ports and connections): one read for all.
                delay(RESHAPE_SETTLE)
                readNetwork()
            }
        }
        coordinator?.let { following -> scope.launch { followCoordinator(following) } }
    }

    /**
     * Everything a page starts from: the network with the states the tree's model holds now (the page
     * then skips the state events up to its sequence), the coordinator, the recent events, what it may do.
     */
    fun snapshot(): Map<String, Any?> = mapOf(
        "network" to withStates(network, tree.snapshot()),
        "coordinator" to coordinatorState,
        "events" to synchronized(recent) { recent.toList() },
        "operable" to operable,
        "serverTime" to Instant.now().toString(),
    )

    /** Adds a line from the coordinator or the server to the timeline. */
    fun log(source: String, line: String) {
        record(mapOf("kind" to "log", "source" to source, "text" to line))
    }

    private suspend fun publish(event: RtcEvent) {
        record(
            event.toJson() + mapOf(
                "kind" to kindOf(event),
                "source" to event.path.toString(),
                "text" to event.what(),
                "noticedAt" to event.noticedAt,
            ),
        )
        // The page applies state changes itself; anything else may change what is drawn.
        if (event !is StateChanged && event !is FsmStateChanged) reshaped.trySend(Unit)
    }

    private fun record(entry: Map<String, Any?>) {
        val numbered = mapOf("seq" to sequence.incrementAndGet(), "sentAt" to System.currentTimeMillis()) + entry +
            (if ("time" in entry) emptyMap() else mapOf("time" to Instant.now().toString()))
        synchronized(recent) {
            recent.addLast(numbered)
            while (recent.size > RECENT_KEPT) recent.removeFirst()
        }
        broadcast.tryEmit(Update("event", toJson(numbered, pretty = false)))
    }

    /** Reads the network again; components that appeared are read first, so they are drawn with their state. */
    private suspend fun readNetwork() {
        NetworkView(top, tree.snapshot()).unread().forEach { component -> readQuietly(component) }
        network = NetworkView(top, tree.snapshot()).toJson()
        broadcast.tryEmit(Update("network", toJson(network, pretty = false)))
    }

    private suspend fun readQuietly(component: ComponentNode) {
        try {
            component.refresh()
        } catch (e: RtcException) {
            // It became a zombie, which the view shows.
        }
    }

    private suspend fun followCoordinator(following: Coordinator) {
        CoordinatorView(following).updates().collect { state ->
            coordinatorState = state
            broadcast.tryEmit(Update("coordinator", toJson(state, pretty = false)))
        }
    }

    /** Stops following the system and the coordinator. */
    override fun close() {
        subscriptions.forEach(Subscription::cancel)
        scope.cancel()
    }

    private companion object {
        /** [network] with each component's state and FSM state as [model] holds them, and [model]'s sequence. */
        @Suppress("UNCHECKED_CAST")
        fun withStates(network: Map<String, Any?>, model: SystemSnapshot): Map<String, Any?> {
            val entries = model.components.flatMap { entry -> entry.paths.map { it.toString() to entry } }.toMap()
            val components = (network["components"] as? List<Map<String, Any?>>).orEmpty().map { component ->
                entries[component["id"]]?.let { component + mapOf("state" to it.overallState.name, "fsm" to it.fsm?.toJson()) } ?: component
            }
            return network + mapOf("components" to components, "sequence" to model.sequence)
        }

        const val BUFFERED = 10_000
        const val RECENT_KEPT = 500
        val RESHAPE_SETTLE = 150.milliseconds

        /** The timeline's filter groups: state, port, configuration, liveness, manager, structure. */
        fun kindOf(event: RtcEvent): String = when (event) {
            is StateChanged, is ContextRunningChanged, is ContextRateChanged, is ContextAttachmentChanged, is ComponentFinalized, is FsmStateChanged -> "state"
            is PortConnected, is PortDisconnected, is PortTraffic -> "port"
            is ParameterChanged, is ConfigurationSetActivated, is ConfigurationSetAdded, is ConfigurationSetRemoved -> "configuration"
            is HeartbeatLost, is BecameZombie, is Recovered, is WatchMethodChanged -> "liveness"
            is ManagerComponentChanged, is ManagerDied, is ManagerReturned -> "manager"
            is NameServerLost, is NameServerReturned -> "liveness"
            is NodeAppeared, is NodeVanished -> "structure"
        }
    }
}
