package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerNode
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerNode
import org.rtcoord.NameServerReturned
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.TimedOutException
import org.rtcoord.UnreachableException
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.TreeCore

/**
 * The outages of the processes watched components stand behind, their managers and their name servers, each told once
 * ([Outages]) to whoever watches something behind it and to the [reports]: a component or a listing that stops
 * answering makes what it stands behind suspected, and a manager found dead has each component it hosted read at once.
 *
 * @param components the component monitors by component, as the tree's watcher holds them now.
 * @param listings the listing monitors by directory, as the tree's watcher holds them now.
 */
internal class ProcessOutages(
    private val core: TreeCore,
    private val reports: WatchReports,
    private val components: () -> Map<ComponentObject, ComponentMonitor>,
    private val listings: () -> Map<RtcPath, ListingMonitor>,
) {
    private val managers =
        Outages<ManagerNode>(
            core,
            { manager -> sinksOf(manager) + reports.all },
            probe = { it.profile() },
            lost = { manager, cause -> ManagerDied(manager, hostedNodes(manager), cause) },
            back = { manager, _ -> ManagerReturned(manager) },
            whenLost = ::managerLost,
        )
    private val nameServers =
        Outages<NameServerNode>(
            core,
            { server -> sinksOf(server) + reports.all },
            probe = { it.relist() },
            lost = ::NameServerLost,
            back = ::NameServerReturned,
        )
    /** The name servers' check while anyone wants reports. */
    private var serverChecks: Job? = null

    /**
     * Lists the name servers every [SERVER_CHECK_PERIOD] while [wanted]: an outage is news even to a coordinator that
     * lists nothing.
     */
    @Synchronized
    fun checkNameServers(wanted: Boolean) {
        serverChecks?.cancel()
        serverChecks = if (wanted) core.scope.launch(core.background.dispatcher) { listNameServers() } else null
    }

    /**
     * [node] stopped answering: the managers that list it are asked whether they still answer, every [period] once
     * dead.
     */
    fun componentSilent(node: ComponentNode, period: Duration) {
        node.component.hostingManagers.forEach { managers.suspect(it, period) }
    }

    /**
     * Listing [directory] failed with [cause]: a manager is asked whether it still answers, and so is the name server
     * of anything else that did not answer, every [period] once found lost.
     */
    fun listingFailed(directory: DirectoryNode, cause: RtcException, period: Duration) {
        when {
            directory is ManagerNode -> managers.suspect(directory, period)
            cause !is UnreachableException && cause !is TimedOutException -> Unit
            else ->
                core
                    .nameServers()
                    .firstOrNull { it.address == directory.path.nameServer }
                    ?.let { nameServers.suspect(it, period) }
        }
    }

    private suspend fun listNameServers() {
        while (true) {
            delay(SERVER_CHECK_PERIOD)
            for (server in core.nameServers()) {
                try {
                    withContext(core.background) { server.relist() }
                } catch (e: RtcException) {
                    listingFailed(server, e, SERVER_CHECK_PERIOD)
                }
            }
        }
    }

    /**
     * [manager] died: each component it hosted is read at once, rather than at its next beat or tick, and found gone
     * with it.
     */
    private fun managerLost(manager: ManagerNode) {
        val hosted = hostedBy(manager)
        components().filterKeys { it in hosted }.values.forEach { it.suspect() }
    }

    /** Where events about [server] go: to whoever watches something registered on it. */
    private fun sinksOf(server: NameServerNode): Set<EventSink> {
        val componentSinks =
            components().values.filter { it.node.path.nameServer == server.address }.flatMap { it.sinks() }
        val listingSinks = listings().filterKeys { it.nameServer == server.address }.values.flatMap { it.sinks() }
        return (componentSinks + listingSinks).toSet()
    }

    /** Where events about [manager] go: to whoever watches it or a component its last listing showed. */
    private fun sinksOf(manager: ManagerNode): Set<EventSink> {
        val hosted = hostedBy(manager)
        val componentSinks = components().filterKeys { it in hosted }.values.flatMap { it.sinks() }
        val listingSinks = listings()[manager.path]?.sinks().orEmpty()
        return (componentSinks + listingSinks).toSet()
    }

    private fun hostedBy(manager: ManagerNode): Set<ComponentObject> = hostedNodes(manager).map { it.component }.toSet()

    /**
     * The components [manager] hosts: those its last listing showed, and the watched ones a master's listing placed in
     * it (a slave may die before its own listing is read).
     */
    private fun hostedNodes(manager: ManagerNode): List<ComponentNode> {
        val listed = manager.listed.value.orEmpty().filterIsInstance<ComponentNode>()
        val placed =
            components()
                .values
                .map { it.node }
                .filter { node ->
                    node.component.hostingManagers.any { it.path == manager.path } &&
                        listed.none { it.component === node.component }
                }
        return listed + placed
    }

    private companion object {
        /** How often the name servers are listed for the reports: as often as a component is polled by default. */
        val SERVER_CHECK_PERIOD = 1.seconds
    }
}
