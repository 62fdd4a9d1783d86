package org.rtcoord.internal.events

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.launch
import org.rtcoord.Overlap
import org.rtcoord.RtcEvent
import org.slf4j.LoggerFactory

/**
 * One registration's delivery: events wait in a channel shaped by its [Overlap] policy and its handler
 * runs in a coroutine of its own, never on the monitor that produced the event, so a handler may call
 * back into the source node, and a slow or failing handler delays nobody else.
 */
internal class EventSink(
    scope: CoroutineScope,
    private val accepts: (RtcEvent) -> Boolean,
    overlap: Overlap,
    private val handler: suspend (RtcEvent) -> Unit,
) {
    private val log = LoggerFactory.getLogger(EventSink::class.java)
    private val pending = Channel<RtcEvent>(
        when (overlap) {
            Overlap.QUEUE -> Channel.UNLIMITED
            Overlap.LATEST -> Channel.CONFLATED
            // Only a handler waiting for its next event takes one; while it runs, offers fail.
            Overlap.SKIP -> Channel.RENDEZVOUS
        },
    )
    private val delivery = scope.launch {
        for (event in pending) {
            try {
                handler(event)
            } catch (e: CancellationException) {
                throw e
            } catch (e: Throwable) {
                log.warn("event handler failed on {}: {}", event, e.toString(), e)
            }
        }
    }

    fun offer(event: RtcEvent) {
        if (accepts(event)) pending.trySend(event)
    }

    fun close() {
        pending.close()
        delivery.cancel()
    }
}
