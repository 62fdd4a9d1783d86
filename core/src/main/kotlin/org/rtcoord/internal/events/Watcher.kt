package org.rtcoord.internal.events

import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ConfigurationSetAdded
import org.rtcoord.ConfigurationSetRemoved
import org.rtcoord.DirectoryNode
import org.rtcoord.EventOptions
import org.rtcoord.HeartbeatLost
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerNode
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerNode
import org.rtcoord.NameServerReturned
import org.rtcoord.Node
import org.rtcoord.Overlap
import org.rtcoord.ParameterChanged
import org.rtcoord.PortTraffic
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.StateChanged
import org.rtcoord.Subscription
import org.rtcoord.TimedOutException
import org.rtcoord.UnreachableException
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged
import org.rtcoord.WrongKindException
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.TreeCore
import org.rtcoord.label
import org.slf4j.LoggerFactory
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/**
 * The tree's registrations: one [ComponentMonitor] per component and one [ListingMonitor] per directory,
 * shared by every registration that needs them and stopped with the last one.
 */
internal class Watcher(private val core: TreeCore) {
    private val host by lazy { ObserverHost(core.orb.orb) }
    private val components = HashMap<ComponentObject, ComponentMonitor>()
    private val live = java.util.concurrent.ConcurrentHashMap.newKeySet<ComponentMonitor>()
    /** By path: a directory listed anew (its name server restarted) is the same directory, listed once. */
    private val listings = HashMap<RtcPath, ListingMonitor>()
    private val reporters = CopyOnWriteArrayList<EventSink>()
    private val managers = Outages<ManagerNode>(
        core, { manager -> sinksOf(manager) + reporters }, probe = { it.profile() },
        lost = { manager, cause -> ManagerDied(manager, manager.listed.value.orEmpty().filterIsInstance<ComponentNode>(), cause) },
        back = { manager, _ -> ManagerReturned(manager) },
        whenLost = ::managerLost,
    )
    private val nameServers = Outages<NameServerNode>(
        core, { server -> sinksOf(server) + reporters }, probe = { it.relist() }, lost = ::NameServerLost, back = ::NameServerReturned,
    )
    private val log = LoggerFactory.getLogger("org.rtcoord.RtcTree")
    private val polls = HashMap<Duration, PollSchedule>()
    /** The name servers' check while anyone wants reports; guarded by [reporters]. */
    private var serverChecks: Job? = null

    /** The heartbeat watchdogs of every component watched by push. */
    val watchdogs = Watchdogs(core.scope)

    /**
     * Delivers the events of [types] (all when null) from [target] to [handler]: a component's own
     * events, or for a directory its listing's events and those of every component below it, including
     * components that appear later.
     */
    suspend fun watch(target: Node, types: Set<Class<out RtcEvent>>?, options: EventOptions, handler: suspend (RtcEvent) -> Unit): Subscription {
        val sink = EventSink(core.scope, { event -> types == null || types.any { it.isInstance(event) } }, options.overlap, handler)
        val configuration = types == null || types.any { it in CONFIGURATION_EVENTS }
        val statesOnly = types != null && types.all { it in STATE_EVENTS }
        val traffic = types != null && PortTraffic::class.java in types
        val releases = mutableListOf<() -> Unit>()
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
                        val monitor = synchronized(components) { components.getOrPut(node.component) { ComponentMonitor(core, host, node.canonical, ::ended).also { live += it } } }
                        monitor.add(registration)
                        synchronized(releases) { releases += { release(node.component, monitor, registration) } }
                    } finally {
                        inclusion.complete(Unit)
                    }
                }
                is DirectoryNode -> synchronized(watched) { watched.add(node.path) }.takeIf { it }?.let {
                    val children = try {
                        node.children()
                    } catch (e: RtcException) {
                        listingFailed(node, e, options.pollPeriod)
                        emptyList()
                    }
                    // Managers listed first, down to their slaves: a component that dies before the walk
                    // reaches its manager is still known as that manager's, and the manager's death told.
                    children.filterIsInstance<ManagerNode>().forEach { listManagers(it) }
                    val registration = ListingMonitor.Registration(sink, options.pollPeriod) { child -> include(child) }
                    val monitor = synchronized(listings) { listings.getOrPut(node.path) { ListingMonitor(core, node) } }
                    monitor.add(registration)
                    synchronized(releases) { releases += { release(node, monitor, registration) } }
                    // Components in naming contexts first, so a monitor's paths are the ones users know.
                    children.sortedBy { it is ManagerNode }.forEach { include(it) }
                }
                else -> if (node === target) throw WrongKindException(node.path.toString(), "component or directory", node.kind.label())
            }
        }

        include(target)
        return Subscription {
            sink.close()
            synchronized(releases) { releases.toList().also { releases.clear() } }.forEach { it() }
        }
    }

    /**
     * Delivers to [handler] how each watched component is watched (now, and again when it changes) and
     * which managers hosting watched components stop or resume answering, whoever asked for the watching.
     */
    fun report(handler: suspend (RtcEvent) -> Unit): Subscription {
        val sink = EventSink(core.scope, { true }, Overlap.QUEUE, handler)
        synchronized(reporters) {
            reporters += sink
            live.forEach { monitor -> monitor.method?.let { sink.offer(WatchMethodChanged(monitor.node, null, it)) } }
            if (serverChecks == null) serverChecks = core.scope.launch { checkNameServers() }
        }
        return Subscription {
            synchronized(reporters) {
                reporters -= sink
                if (reporters.isEmpty()) serverChecks?.cancel().also { serverChecks = null }
            }
            sink.close()
        }
    }

    /** Lists the name servers every [SERVER_CHECK_PERIOD] while anyone wants reports: an outage is news even to a coordinator that lists nothing. */
    private suspend fun checkNameServers() {
        while (true) {
            delay(SERVER_CHECK_PERIOD)
            for (server in core.nameServers()) {
                try {
                    server.relist()
                } catch (e: RtcException) {
                    listingFailed(server, e, SERVER_CHECK_PERIOD)
                }
            }
        }
    }

    /**
     * Records that [monitor] watches its component by [method], telling the reporters if that is news and
     * each of its [registrations] not yet told; called from the monitor's coroutine, which owns `told`.
     */
    fun announce(monitor: ComponentMonitor, method: WatchMethod, registrations: List<MonitorRegistration>) {
        synchronized(reporters) {
            val old = monitor.method
            if (old != method) {
                monitor.method = method
                core.model.publish(listOf(WatchMethodChanged(monitor.node, old, method))) { event -> reporters.forEach { it.offer(event) } }
            }
        }
        for (registration in registrations) {
            if (registration.told == method) continue
            core.model.publish(listOf(WatchMethodChanged(monitor.node, registration.told, method))) { registration.sink.offer(it) }
            registration.told = method
        }
    }

    /** Reads [member] every [period], on the schedule of every component polled at that period. */
    fun poll(period: Duration, member: PollSchedule.Member) {
        synchronized(polls) {
            polls.getOrPut(period) {
                val slow = { members: Int, achieved: Duration ->
                    log.warn(
                        "polling {} components every {} cannot keep up: each is read every {} ({}) instead",
                        members, period, achieved.inWholeMilliseconds.milliseconds, achieved.asRate(),
                    )
                }
                PollSchedule(core.scope, period, POLLS_IN_FLIGHT, { core.missedPollTicks.addAndGet(it) }, slow, context = core.remote.dispatcher)
            }.add(member)
        }
    }

    /** Stops reading [member] every [period]. */
    fun unpoll(period: Duration, member: PollSchedule.Member) {
        synchronized(polls) {
            val schedule = polls[period] ?: return
            if (schedule.remove(member)) {
                polls.remove(period)
                schedule.stop()
            }
        }
    }

    /** [manager] died: each component it hosted is read at once, rather than at its next beat or tick, and found gone with it. */
    private fun managerLost(manager: ManagerNode) {
        val hosted = manager.listed.value.orEmpty().filterIsInstance<ComponentNode>().map { it.component }.toSet()
        synchronized(components) { components.filterKeys { it in hosted }.values.toList() }.forEach { it.suspect() }
    }

    /** [node] stopped answering: the managers that list it are asked whether they still answer, every [period] once dead. */
    fun componentSilent(node: ComponentNode, period: Duration) {
        node.component.hostingManagers.forEach { managers.suspect(it, period) }
    }

    /**
     * Listing [directory] failed with [cause]: a manager is asked whether it still answers, and so is the
     * name server of anything else that did not answer, every [period] once found lost.
     */
    fun listingFailed(directory: DirectoryNode, cause: RtcException, period: Duration) {
        when {
            directory is ManagerNode -> managers.suspect(directory, period)
            cause !is UnreachableException && cause !is TimedOutException -> Unit
            else -> core.nameServers().firstOrNull { it.address == directory.path.nameServer }?.let { nameServers.suspect(it, period) }
        }
    }

    /** Where events about [server] go: to whoever watches something registered on it. */
    private fun sinksOf(server: NameServerNode): Set<EventSink> {
        val componentSinks = synchronized(components) { components.values.filter { it.node.path.nameServer == server.address }.flatMap { it.sinks() } }
        val listingSinks = synchronized(listings) { listings.filterKeys { it.nameServer == server.address }.values.flatMap { it.sinks() } }
        return (componentSinks + listingSinks).toSet()
    }

    /** Where events about [manager] go: to whoever watches it or a component its last listing showed. */
    private fun sinksOf(manager: ManagerNode): Set<EventSink> {
        val hosted = manager.listed.value.orEmpty().filterIsInstance<ComponentNode>().map { it.component }.toSet()
        val componentSinks = synchronized(components) { components.filterKeys { it in hosted }.values.flatMap { it.sinks() } }
        val listingSinks = synchronized(listings) { listings[manager.path]?.sinks().orEmpty() }
        return (componentSinks + listingSinks).toSet()
    }

    /** Lists [manager] and its slaves (once: listings are cached), each recording the components it hosts. */
    private suspend fun listManagers(manager: ManagerNode) {
        val children = try { manager.children() } catch (e: RtcException) { return }
        children.filterIsInstance<ManagerNode>().forEach { listManagers(it) }
    }

    private fun ended(monitor: ComponentMonitor) {
        live.remove(monitor)
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
     * Stops every monitor, including those already stopping, and returns once each has detached its
     * observer (or a call deadline and a second have passed for the slowest): the tree's scope and ORB
     * must outlive the detaching.
     */
    fun close() {
        synchronized(components) { components.clear() }
        // Copied in one step: toList() reads the size and then the elements, which monitors ending meanwhile remove.
        val stopping = ArrayList(live)
        stopping.forEach(ComponentMonitor::stop)
        stopping.forEach { it.awaitStopped(core.config.callTimeout + 1.seconds) }
        synchronized(listings) { listings.values.forEach(ListingMonitor::stop); listings.clear() }
        synchronized(polls) { polls.values.forEach(PollSchedule::stop); polls.clear() }
        watchdogs.close()
        reporters.forEach(EventSink::close)
    }

    private companion object {
        /**
         * Poll reads pending at once, whatever the number of components. Measured polling 1000 fixtures at
         * 10 Hz (bench/README.md, "where the time goes"): 2 to 4 in flight read as many components a second
         * as 32 for less CPU per read (96 against 118 us); 16 made JacORB's request pool thrash.
         */
        const val POLLS_IN_FLIGHT = 4

        /** How often the name servers are listed for the reports: as often as a component is polled by default. */
        val SERVER_CHECK_PERIOD = 1.seconds

        /** Events a read of the lifecycle states alone can produce. */
        val STATE_EVENTS = setOf(
            StateChanged::class.java, HeartbeatLost::class.java, BecameZombie::class.java,
            Recovered::class.java, ComponentFinalized::class.java, WatchMethodChanged::class.java,
            ManagerDied::class.java, ManagerReturned::class.java, PortTraffic::class.java,
            NameServerLost::class.java, NameServerReturned::class.java,
        )

        val CONFIGURATION_EVENTS = setOf(
            ParameterChanged::class.java, ConfigurationSetActivated::class.java,
            ConfigurationSetAdded::class.java, ConfigurationSetRemoved::class.java, RtcEvent::class.java,
        )
    }
}
