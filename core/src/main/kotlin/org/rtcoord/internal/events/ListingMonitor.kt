package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.ManagerComponentChanged
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.internal.TreeCore
import org.slf4j.LoggerFactory

/**
 * Watches a directory's children by listing them again at the shortest period its registrations ask for (naming
 * services and managers push nothing): a naming context reports nodes appearing and vanishing, a manager reports
 * components it created and deleted. What is reported is every change of the directory's listing, whoever listed it: a
 * component the tree created itself (`ManagerNode.create` lists its naming context) is reported, and watched by the
 * registrations that include what appears, at once rather than at the next period, which a component that exits soon
 * after would not outlive.
 */
internal class ListingMonitor(private val core: TreeCore, private val directory: DirectoryNode) {
    /** [appeared] starts watching a new child; its events are offered once it returns. */
    class Registration(val sink: EventSink, val period: Duration, val appeared: suspend (Node) -> Unit)

    private val log = LoggerFactory.getLogger(ListingMonitor::class.java)
    private val registrations = CopyOnWriteArrayList<Registration>()
    private var poller: Job? = null
    private var announcer: Job? = null
    private var period: Duration? = null

    @Synchronized
    fun add(registration: Registration) {
        registrations += registration
        if (announcer == null) announcer = announceChanges()
        reschedule()
    }

    /** Removes [registration]; returns whether none is left. */
    @Synchronized
    fun remove(registration: Registration): Boolean {
        registrations -= registration
        reschedule()
        return registrations.isEmpty()
    }

    private fun reschedule() {
        val shortest = registrations.minOfOrNull { it.period }
        if (shortest == period) return
        poller?.cancel()
        period = shortest
        poller = shortest?.let { every ->
            // On the listings' few threads (TreeCore.background); what the listing finds is read at full concurrency.
            core.scope.launch(core.background.dispatcher) {
                var failing = false
                var listings = 0L
                while (isActive) {
                    delay(every)
                    val resolveAll = listings++ % RESOLVED_EVERY == 0L
                    try {
                        withContext(core.background) {
                            if (resolveAll) directory.relist() else directory.relist(::watchedAndAnswering)
                        }
                    } catch (e: RtcException) {
                        if (!failing) log.info("{}; listing it again every {}", e.message, every)
                        // Every time: a server shutting down first answers wrongly, and only then not at all.
                        core.watcher.outages.listingFailed(directory, e, every)
                        failing = true
                        continue
                    }
                    if (failing) log.info("{}: listed again", directory.path)
                    failing = false
                }
            }
        }
    }

    /** Announces each change of the directory's listing, one after another, from the listing it has now. */
    private fun announceChanges(): Job {
        // Taken now, not once the coroutine runs: a listing made meanwhile is a change to announce.
        var before = directory.listed.value
        return core.scope.launch(core.background.dispatcher) {
            directory.listed.collect { after ->
                // Never listed before: the first listing failed, and all it finds now is news.
                if (after == null || after == before) return@collect
                announce(before.orEmpty(), after)
                before = after
            }
        }
    }

    private suspend fun announce(before: List<Node>, after: List<Node>) {
        val old = before.associateBy { it.name }
        val new = after.associateBy { it.name }
        val appeared = (new.keys - old.keys).map(new::getValue)
        val vanished = (old.keys - new.keys).map(old::getValue)
        // Watched before announced: a handler acting on a new node misses none of its events, and what
        // happened to a component before it was found is in the snapshot its appearance carries.
        for (registration in registrations) appeared.forEach { registration.appeared(it) }
        val events: List<RtcEvent> =
            if (directory is ManagerNode) {
                appeared.filterIsInstance<ComponentNode>().map {
                    ManagerComponentChanged(directory, it.name.removeSuffix(".rtc"), created = true)
                } +
                    vanished.filterIsInstance<ComponentNode>().map {
                        ManagerComponentChanged(directory, it.name.removeSuffix(".rtc"), created = false)
                    }
            } else {
                appeared.map { NodeAppeared(directory, it, (it as? ComponentNode)?.snapshots?.value) } +
                    vanished.map { NodeVanished(directory, it.path) }
            }
        core.model.publish(events) { event -> registrations.forEach { it.sink.offer(event) } }
    }

    /** Whether [node] is a component whose monitor would notice it stop answering: its binding needs no resolving. */
    private fun watchedAndAnswering(node: Node): Boolean = node is ComponentNode && core.model.answers(node.component)

    /** Where the registrations' events go. */
    fun sinks(): List<EventSink> = registrations.map { it.sink }

    fun stop() {
        poller?.cancel()
        announcer?.cancel()
    }

    private companion object {
        /**
         * Every how many listings the bindings of watched components that answer are resolved again: the others are
         * resolved at each. A thousand components bound in one context cost a thousand `resolve` calls a listing, while
         * a watched component's monitor notices it stop answering, and its name is resolved then. A name bound again to
         * another component while the first still answers is noticed within this many periods.
         */
        const val RESOLVED_EVERY = 10L
    }
}
