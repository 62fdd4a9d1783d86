package org.rtcoord.internal.events

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.launch
import org.rtcoord.Overlap
import org.rtcoord.RtcEvent

/**
 * One registration's delivery: events wait in a channel shaped by its [Overlap] policy and its handler runs in a
 * coroutine of its own, never on the monitor that produced the event, so a handler may call back into the source node,
 * and a slow or failing handler delays nobody else. What a handler throws goes to the tree's [ListenerFailures], found
 * in [scope]'s context.
 */
internal class EventSink(
    scope: CoroutineScope,
    private val accepts: (RtcEvent) -> Boolean,
    overlap: Overlap,
    private val handler: suspend (RtcEvent) -> Unit,
    /**
     * With [Overlap.QUEUE], the most events that wait for the handler, the oldest dropped and told to [dropped] when
     * more come: for streams the handler need not see whole (log records), so that a slow handler costs no more memory.
     */
    bound: Int? = null,
    private val dropped: () -> Unit = {},
) {
    @Volatile private var closed = false

    private val failures =
        checkNotNull(scope.coroutineContext[ListenerFailures]) { "event sinks deliver in a tree's scope" }
    private val listener: Any = (handler as? StandIn)?.listener ?: handler
    private val pending =
        if (overlap == Overlap.QUEUE && bound != null)
            Channel<RtcEvent>(bound, BufferOverflow.DROP_OLDEST) { if (!closed) dropped() }
        else
            Channel(
                when (overlap) {
                    Overlap.QUEUE -> Channel.UNLIMITED
                    Overlap.LATEST -> Channel.CONFLATED
                    // Only a handler waiting for its next event takes one; while it runs, offers fail.
                    Overlap.SKIP -> Channel.RENDEZVOUS
                }
            )
    private val delivery = scope.launch {
        for (event in pending) {
            try {
                handler(event)
            } catch (e: CancellationException) {
                throw e
            } catch (e: Throwable) {
                failures.report(listener, event, e)
            }
        }
    }

    fun offer(event: RtcEvent) {
        if (accepts(event)) pending.trySend(event)
    }

    fun close() {
        closed = true
        pending.close()
        delivery.cancel()
    }
}
