package org.rtcoord.internal.events

import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CompletableDeferred
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ConfigurationSetAdded
import org.rtcoord.ConfigurationSetRemoved
import org.rtcoord.DirectoryNode
import org.rtcoord.EventOptions
import org.rtcoord.HeartbeatLost
import org.rtcoord.LogRecord
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerNode
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerReturned
import org.rtcoord.Node
import org.rtcoord.ParameterChanged
import org.rtcoord.PortTraffic
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.StateChanged
import org.rtcoord.Subscription
import org.rtcoord.WatchMethodChanged
import org.rtcoord.WrongKindException
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.logs.LogRecords
import org.rtcoord.label

/**
 * The tree's registrations: one [ComponentMonitor] per component and one [ListingMonitor] per directory, shared by
 * every registration that needs them and stopped with the last one. What the monitors share is its parts': the [polls],
 * the [watchdogs], the [reports] and the [outages].
 */
internal class Watcher(private val core: TreeCore) {
    private val host by lazy { ObserverHost(core.orb::rootPoa, core.orb.inbound, core::execute) }
    private val components = HashMap<ComponentObject, ComponentMonitor>()
    private val live = java.util.concurrent.ConcurrentHashMap.newKeySet<ComponentMonitor>()
    /** By path: a directory listed anew (its name server restarted) is the same directory, listed once. */
    private val listings = HashMap<RtcPath, ListingMonitor>()

    /** The poll schedules of every component watched by polling. */
    val polls = PollSchedules(core)

    /** How often observers may beat, for the number of components watched. */
    val heartbeats = HeartbeatBudget { ArrayList(live).forEach(ComponentMonitor::rearrange) }

    /** The heartbeat watchdogs of every component watched by push. */
    val watchdogs = Watchdogs(core.scope, core.time, core.clock)

    /** Those who want reports of the watching itself. */
    val reports = WatchReports(core)

    /** The outages of the managers and name servers watched components stand behind. */
    val outages =
        ProcessOutages(
            core,
            reports,
            { synchronized(components) { HashMap(components) } },
            { synchronized(listings) { HashMap(listings) } },
        )

    /**
     * Delivers the events of [types] (all when null) from [target] to [handler]: a component's own events, or for a
     * directory its listing's events and those of every component below it, including components that appear later.
     */
    suspend fun watch(
        target: Node,
        types: Set<Class<out RtcEvent>>?,
        options: EventOptions,
        handler: suspend (RtcEvent) -> Unit,
    ): Subscription {
        val recordsOnly = types != null && types.all { LogRecord::class.java.isAssignableFrom(it) }
        // Checked before anything starts: records come to components and directories only.
        if (recordsOnly && target !is ComponentNode && target !is DirectoryNode)
            throw WrongKindException(target.path.toString(), "component or directory", target.kind.label())
        val sink =
            EventSink(
                core.scope,
                { event -> types == null || types.any { it.isInstance(event) } },
                options.overlap,
                handler,
                // A handler of records alone that falls behind loses the oldest, counted: records may come faster
                // than any handler takes them, and must not fill the heap.
                bound = if (recordsOnly) LogRecords.HANDLER_QUEUE else null,
                dropped = core.logs::droppedByHandler,
            )
        val configuration = types == null || types.any { it in CONFIGURATION_EVENTS }
        val statesOnly = types != null && types.all { it in STATE_EVENTS }
        val traffic = types != null && PortTraffic::class.java in types
        // One for a component; a directory's grows as its listings find components.
        val releases = ArrayList<() -> Unit>(1)
        if (types == null || types.any { it.isAssignableFrom(LogRecord::class.java) }) {
            releases += core.logs.add(sink, target)
            // Records come from the log inputs, not from the components: hearing them alone watches nothing.
            if (recordsOnly) {
                return Subscription {
                    sink.close()
                    releases.forEach { it() }
                }
            }
        }
        val watched = HashSet<RtcPath>()
        // A component reached by two paths at once (its naming context, its manager) is included once;
        // the second caller waits until it is watched, as the first does.
        val included = HashMap<ComponentObject, CompletableDeferred<Unit>>()

        suspend fun include(node: Node) {
            when (node) {
                is ComponentNode -> {
                    val inclusion = CompletableDeferred<Unit>()
                    val earlier = synchronized(included) { included.putIfAbsent(node.component, inclusion) }
                    if (earlier != null) return earlier.await()
                    try {
                        // Its events name it at its canonical path, whichever path led here first.
                        val registration = MonitorRegistration(sink, options, configuration, statesOnly, traffic)
                        val monitor =
                            synchronized(components) {
                                components.getOrPut(node.component) {
                                    ComponentMonitor(core, host, node.canonical, ::ended).also { live += it }
                                }
                            }
                        heartbeats.watching(live.size)
                        monitor.add(registration)
                        synchronized(releases) { releases += { release(node.component, monitor, registration) } }
                    } finally {
                        inclusion.complete(Unit)
                    }
                }
                is DirectoryNode ->
                    synchronized(watched) { watched.add(node.path) }
                        .takeIf { it }
                        ?.let {
                            var failure: RtcException? = null
                            val children =
                                try {
                                    node.children()
                                } catch (e: RtcException) {
                                    failure = e
                                    emptyList()
                                }
                            // Managers listed first, down to their slaves: a component that dies before the walk
                            // reaches its manager is still known as that manager's, and the manager's death told.
                            children.filterIsInstance<ManagerNode>().forEach { listManagers(it) }
                            val registration =
                                ListingMonitor.Registration(sink, options.pollPeriod) { child -> include(child) }
                            val monitor =
                                synchronized(listings) { listings.getOrPut(node.path) { ListingMonitor(core, node) } }
                            monitor.add(registration)
                            synchronized(releases) { releases += { release(node, monitor, registration) } }
                            // Said once this registration is there to hear it: a name server found down at once is
                            // reported to it.
                            failure?.let { outages.listingFailed(node, it, options.pollPeriod) }
                            // Components in naming contexts first, so a monitor's paths are the ones users know.
                            children.sortedBy { it is ManagerNode }.forEach { include(it) }
                        }
                else ->
                    if (node === target)
                        throw WrongKindException(node.path.toString(), "component or directory", node.kind.label())
            }
        }

        include(target)
        return Subscription {
            sink.close()
            synchronized(releases) { releases.toList().also { releases.clear() } }.forEach { it() }
        }
    }

    /**
     * Delivers to [handler] how each watched component is watched (now, and again when it changes) and which managers
     * and name servers watched components stand behind stop or resume answering, whoever asked for the watching.
     */
    fun report(handler: suspend (RtcEvent) -> Unit): Subscription =
        reports.add(handler, live, outages::checkNameServers)

    /** Lists [manager] and its slaves (once: listings are cached), each recording the components it hosts. */
    private suspend fun listManagers(manager: ManagerNode) {
        val children =
            try {
                manager.children()
            } catch (e: RtcException) {
                return
            }
        children.filterIsInstance<ManagerNode>().forEach { listManagers(it) }
    }

    private fun ended(monitor: ComponentMonitor) {
        live.remove(monitor)
        heartbeats.watching(live.size)
        core.model.unwatched(monitor.node.component)
    }

    private fun release(component: ComponentObject, monitor: ComponentMonitor, registration: MonitorRegistration) {
        synchronized(components) {
            if (monitor.remove(registration)) {
                components.remove(component)
                monitor.stop()
            }
        }
    }

    private fun release(directory: DirectoryNode, monitor: ListingMonitor, registration: ListingMonitor.Registration) {
        synchronized(listings) {
            if (monitor.remove(registration)) {
                listings.remove(directory.path)
                monitor.stop()
            }
        }
    }

    /**
     * Stops every monitor, including those already stopping, and returns once each has detached its observer (or a call
     * deadline and a second have passed for the slowest): the tree's scope and ORB must outlive the detaching.
     */
    fun close() {
        synchronized(components) { components.clear() }
        // Copied in one step: toList() reads the size and then the elements, which monitors ending meanwhile remove.
        val stopping = ArrayList(live)
        stopping.forEach(ComponentMonitor::stop)
        stopping.forEach { it.awaitStopped(core.config.callTimeout + 1.seconds) }
        synchronized(listings) {
            listings.values.forEach(ListingMonitor::stop)
            listings.clear()
        }
        polls.close()
        watchdogs.close()
        reports.close()
    }

    private companion object {
        /** Events a read of the lifecycle states alone can produce. */
        val STATE_EVENTS =
            setOf(
                StateChanged::class.java,
                HeartbeatLost::class.java,
                BecameZombie::class.java,
                Recovered::class.java,
                ComponentFinalized::class.java,
                WatchMethodChanged::class.java,
                ManagerDied::class.java,
                ManagerReturned::class.java,
                PortTraffic::class.java,
                NameServerLost::class.java,
                NameServerReturned::class.java,
            )

        val CONFIGURATION_EVENTS =
            setOf(
                ParameterChanged::class.java,
                ConfigurationSetActivated::class.java,
                ConfigurationSetAdded::class.java,
                ConfigurationSetRemoved::class.java,
                RtcEvent::class.java,
            )
    }
}
