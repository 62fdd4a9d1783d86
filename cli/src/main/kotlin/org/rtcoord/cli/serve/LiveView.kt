package org.rtcoord.cli.serve

import java.time.Instant
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration.Companion.milliseconds
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
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.encodeToJsonElement
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
import org.rtcoord.LogRecord
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
import org.rtcoord.cli.json.EventJson
import org.rtcoord.cli.json.FsmJson
import org.rtcoord.cli.json.OneLineJson
import org.rtcoord.cli.what
import org.rtcoord.dsl.Coordinator

/**
 * The live state the page shows, derived from the tree's events below [top] and, when there is one, the [coordinator]'s
 * observable state: a snapshot for a page that (re)connects, then [updates]: `event` for each event and log line,
 * `network` when the network's shape may have changed, `coordinator` when the coordinator's state did.
 */
internal class LiveView(
    private val tree: RtcTree,
    private val top: Node,
    private val coordinator: Coordinator?,
    private val options: EventOptions,
    /** Whether the page may operate components. */
    val operable: Boolean,
) : AutoCloseable {
    /** One message to every connected page: its SSE event name and its [data], which pages receive as [json]. */
    class Update(val kind: String, val data: JsonElement) {
        val json: String = OneLineJson.encodeToString(data)
    }

    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default + CoroutineName("live-view"))
    private val broadcast =
        MutableSharedFlow<Update>(extraBufferCapacity = BUFFERED, onBufferOverflow = BufferOverflow.DROP_OLDEST)
    private val recent = ArrayDeque<TimelineEntryJson>()
    private val sequence = AtomicLong()
    private val reshaped = Channel<Unit>(Channel.CONFLATED)
    private val subscriptions = CopyOnWriteArrayList<Subscription>()
    @Volatile private var network: NetworkJson? = null
    @Volatile private var coordinatorState: CoordinatorJson? = null

    /** What happens after a page took its [snapshot]. */
    val updates: SharedFlow<Update> = broadcast.asSharedFlow()

    /** Reads the system, subscribes to its events and starts following the coordinator. */
    suspend fun start() {
        discover(top, null)
        val watched = if (top is RootNode) tree.nameServers else listOf(top)
        subscriptions +=
            tree.follow(
                watched,
                setOf(RtcEvent::class.java),
                options,
                start = { model -> network = NetworkView(top, model).toJson() },
            ) {
                publish(it)
            }
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
     * Everything a page starts from: the network with the states the tree's model holds now (the page then skips the
     * state events up to its sequence), the coordinator, the recent events, what it may do.
     */
    fun snapshot(): LiveSnapshotJson =
        LiveSnapshotJson(
            network?.let { withStates(it, tree.snapshot()) },
            coordinatorState,
            synchronized(recent) { recent.toList() },
            operable,
            Instant.now().toString(),
        )

    /** Adds a line from the coordinator or the server to the timeline. */
    fun log(source: String, line: String) {
        record { seq, sentAt ->
            TimelineEntryJson(seq, sentAt, kind = "log", source = source, text = line, time = Instant.now().toString())
        }
    }

    private suspend fun publish(event: RtcEvent) {
        val json = EventJson.of(event)
        record { seq, sentAt ->
            TimelineEntryJson(seq, sentAt, json, kindOf(event), event.path.toString(), event.what(), event.noticedAt)
        }
        // The page applies state changes itself; anything else may change what is drawn.
        if (event !is StateChanged && event !is FsmStateChanged) reshaped.trySend(Unit)
    }

    /** Adds the entry [numbered] makes from its number and the time it is sent. */
    private fun record(numbered: (seq: Long, sentAt: Long) -> TimelineEntryJson) {
        val entry = numbered(sequence.incrementAndGet(), System.currentTimeMillis())
        synchronized(recent) {
            recent.addLast(entry)
            while (recent.size > RECENT_KEPT) recent.removeFirst()
        }
        broadcast.tryEmit(Update("event", OneLineJson.encodeToJsonElement(entry)))
    }

    /** Reads the network again; components that appeared are read first, so they are drawn with their state. */
    private suspend fun readNetwork() {
        NetworkView(top, tree.snapshot()).unread().forEach { component -> readQuietly(component) }
        val read = NetworkView(top, tree.snapshot()).toJson()
        network = read
        broadcast.tryEmit(Update("network", OneLineJson.encodeToJsonElement(read)))
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
            broadcast.tryEmit(Update("coordinator", OneLineJson.encodeToJsonElement(state)))
        }
    }

    /** Stops following the system and the coordinator. */
    override fun close() {
        subscriptions.forEach(Subscription::cancel)
        scope.cancel()
    }

    private companion object {
        /** [network] with each component's state and FSM state as [model] holds them, and [model]'s sequence. */
        fun withStates(network: NetworkJson, model: SystemSnapshot): NetworkJson {
            val entries = model.components.flatMap { entry -> entry.paths.map { it.toString() to entry } }.toMap()
            val components =
                network.components.map { component ->
                    entries[component.id]?.let {
                        component.copy(state = it.overallState.name, fsm = it.fsm?.let(FsmJson::of))
                    } ?: component
                }
            return network.copy(components = components, sequence = model.sequence)
        }

        const val BUFFERED = 10_000
        const val RECENT_KEPT = 500
        val RESHAPE_SETTLE = 150.milliseconds

        /**
         * The timeline's filter groups: state, port, configuration, liveness, manager, structure, record (a component's
         * log record; "log" is the coordinator's).
         */
        fun kindOf(event: RtcEvent): String =
            when (event) {
                is StateChanged,
                is ContextRunningChanged,
                is ContextRateChanged,
                is ContextAttachmentChanged,
                is ComponentFinalized,
                is FsmStateChanged -> "state"
                is PortConnected,
                is PortDisconnected,
                is PortTraffic -> "port"
                is ParameterChanged,
                is ConfigurationSetActivated,
                is ConfigurationSetAdded,
                is ConfigurationSetRemoved -> "configuration"
                is HeartbeatLost,
                is BecameZombie,
                is Recovered,
                is WatchMethodChanged -> "liveness"
                is ManagerComponentChanged,
                is ManagerDied,
                is ManagerReturned -> "manager"
                is NameServerLost,
                is NameServerReturned -> "liveness"
                is NodeAppeared,
                is NodeVanished -> "structure"
                is LogRecord -> "record"
            }
    }
}
