package org.rtcoord.internal.events

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Job
import kotlinx.coroutines.launch
import org.rtcoord.Overlap
import org.rtcoord.RtcEvent

/**
 * One registration's delivery: events wait in a queue shaped by its [Overlap] policy and its handler runs in a
 * coroutine of its own, never on the monitor that produced the event, so a handler may call back into the source node,
 * and a slow or failing handler delays nobody else. What a handler throws goes to the tree's [ListenerFailures], found
 * in [scope]'s context.
 *
 * The coroutine lives only while there are events to hand over: an event offered to an idle sink starts one, which ends
 * once the queue is empty. A tree watching ten thousand components holds as many sinks, nearly all idle, and a
 * coroutine suspended on a channel for each would weigh more than the rest of the sink.
 */
internal class EventSink(
    private val scope: CoroutineScope,
    private val accepts: (RtcEvent) -> Boolean,
    private val overlap: Overlap,
    private val handler: suspend (RtcEvent) -> Unit,
    /**
     * With [Overlap.QUEUE], the most events that wait for the handler, the oldest dropped and told to [dropped] when
     * more come: for streams the handler need not see whole (log records), so that a slow handler costs no more memory.
     */
    private val bound: Int? = null,
    private val dropped: () -> Unit = {},
) {
    private val failures =
        checkNotNull(scope.coroutineContext[ListenerFailures]) { "event sinks deliver in a tree's scope" }
    private val listener: Any = (handler as? StandIn)?.listener ?: handler

    // Guarded by itself.
    private val waiting = ArrayDeque<RtcEvent>()
    /** The coroutine handing events over, null while the sink is idle. */
    private var delivery: Job? = null
    private var closed = false

    fun offer(event: RtcEvent) {
        if (!accepts(event)) return
        var overflowed = false
        var started: Job? = null
        synchronized(waiting) {
            if (closed) return
            if (delivery == null) {
                // The event is the handler's from now, though its coroutine has yet to run: what comes before it does
                // waits behind it, as it would behind a handler already running. Started once it is known as the
                // delivery, which it clears when it finds nothing more.
                started = scope.launch(start = CoroutineStart.LAZY) { deliver(event) }
                delivery = started
            } else {
                when (overlap) {
                    Overlap.QUEUE -> {
                        if (bound != null && waiting.size >= bound) {
                            waiting.removeFirst()
                            overflowed = true
                        }
                        waiting.addLast(event)
                    }
                    Overlap.LATEST -> {
                        waiting.clear()
                        waiting.addLast(event)
                    }
                    // Only an idle handler takes an event; while it runs, offers are dropped.
                    Overlap.SKIP -> Unit
                }
            }
        }
        started?.start()
        if (overflowed) dropped()
    }

    private suspend fun deliver(first: RtcEvent) {
        var event: RtcEvent? = first
        while (event != null) {
            try {
                handler(event)
            } catch (e: CancellationException) {
                throw e
            } catch (e: Throwable) {
                failures.report(listener, event, e)
            }
            event = synchronized(waiting) { waiting.removeFirstOrNull().also { if (it == null) delivery = null } }
        }
    }

    fun close() {
        val running =
            synchronized(waiting) {
                closed = true
                waiting.clear()
                delivery
            }
        running?.cancel()
    }
}
