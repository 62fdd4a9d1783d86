package org.rtcoord.dsl.internal

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.launch
import org.rtcoord.EventOptions
import org.rtcoord.Overlap
import org.slf4j.LoggerFactory

/**
 * Runs [handler] on the events offered to it, one at a time and in order, in a coroutine of [scope]: each listener of a
 * shared subscription gets its own, so a slow handler delays only itself. An event offered while the handler runs is
 * kept or dropped as [overlap] says. A handler that throws is logged and goes on with the next event.
 */
internal class HandlerQueue<E>(scope: CoroutineScope, overlap: Overlap, private val handler: suspend (E) -> Unit) {
    private val pending =
        Channel<E>(
            when (overlap) {
                Overlap.QUEUE -> Channel.UNLIMITED
                Overlap.LATEST -> Channel.CONFLATED
                Overlap.SKIP -> Channel.RENDEZVOUS
            }
        )

    init {
        // Undispatched, so it waits in its first receive before this returns: an event offered to the idle handler is
        // its own then, and a burst that comes before the coroutine gets a thread neither conflates nor skips it.
        scope.launch(start = CoroutineStart.UNDISPATCHED) {
            for (event in pending) {
                catchFailure({ handler(event) }) { e ->
                    logger.warn("handler failed on {}: {}", event, e.toString(), e)
                }
            }
        }
    }

    /** Hands [event] to the handler, now or once it is free, unless [overlap] drops it. */
    fun offer(event: E) {
        pending.trySend(event)
    }

    private companion object {
        val logger = LoggerFactory.getLogger(HandlerQueue::class.java)
    }
}

/**
 * These options with every event queued: a subscription shared by several listeners must lose nothing; the listeners
 * that drop events under load do so in their own [HandlerQueue].
 */
internal fun EventOptions.queued(): EventOptions = newBuilder().overlap(Overlap.QUEUE).build()
