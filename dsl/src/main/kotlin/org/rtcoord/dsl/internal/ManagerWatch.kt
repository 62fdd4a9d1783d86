package org.rtcoord.dsl.internal

import java.util.concurrent.ConcurrentHashMap
import org.rtcoord.EventOptions
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerNode
import org.rtcoord.ManagerReturned
import org.rtcoord.RtcEvent
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.Subscription

/**
 * Says in a running coordinator's log when a manager dies or answers again, as soon as the tree tells, instead of
 * leaving it to the next creation to fail: the managers its script uses, each watched from when the script names it or
 * first uses it on one subscription that covers its slaves too, and those the tree finds dead because they hosted a
 * component it watches. Each death and return is said once, however many of these it concerns: the tree publishes each
 * as one event, with one sequence number, to every subscription it reaches. Whether a manager answers is the tree's to
 * know ([RtcTree.snapshot]'s `deadManagers`), not this log's.
 */
internal class ManagerWatch(
    private val tree: RtcTree,
    private val options: EventOptions,
    private val log: (String) -> Unit,
) : AutoCloseable {
    private val watched = ConcurrentHashMap<RtcPath, Subscription>()
    /** The sequence numbers of the deaths and returns said. */
    private val said = ConcurrentHashMap.newKeySet<Long>()
    @Volatile private var hosting: Subscription? = null
    @Volatile private var closed = false

    /** Starts hearing of the managers the tree finds dead. */
    fun start() {
        hosting = tree.onWatching(::report)
    }

    /** Watches [manager], unless it is watched already. */
    suspend fun watch(manager: ManagerNode) {
        if (closed || watched.containsKey(manager.path)) return
        val subscription = tree.on(manager, LIVENESS, options.queued(), ::report)
        if (watched.putIfAbsent(manager.path, subscription) != null || closed) subscription.cancel()
    }

    private fun report(event: RtcEvent) {
        when (event) {
            is ManagerDied ->
                if (said.add(event.sequence)) {
                    val hosted =
                        if (event.components.isEmpty()) "it hosted no component"
                        else "its components went with it: ${event.components.joinToString { it.name }}"
                    log("${event.source.path} manager stopped answering (${event.cause.reason}); $hosted")
                }
            is ManagerReturned -> if (said.add(event.sequence)) log("${event.source.path} manager answers again")
            else -> Unit
        }
    }

    /** Stops watching. */
    override fun close() {
        closed = true
        hosting?.cancel()
        watched.values.forEach(Subscription::cancel)
        watched.clear()
    }

    private companion object {
        val LIVENESS: Set<Class<out RtcEvent>> = setOf(ManagerDied::class.java, ManagerReturned::class.java)
    }
}
