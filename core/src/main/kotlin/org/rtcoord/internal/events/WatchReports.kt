package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import org.rtcoord.Overlap
import org.rtcoord.RtcEvent
import org.rtcoord.Subscription
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged
import org.rtcoord.internal.TreeCore

/**
 * Those who want reports of the watching itself, whoever asked for it: how each watched component is watched
 * ([WatchMethodChanged], now and when it changes), and the outages of what components stand behind.
 */
internal class WatchReports(private val core: TreeCore) {
    private val sinks = CopyOnWriteArrayList<EventSink>()

    /** Where every report goes now. */
    val all: List<EventSink>
        get() = sinks

    /**
     * Delivers the reports to [handler], starting with how each of [monitors] is watched now; [wanted] is told when the
     * first report is wanted (true) and when the last is not any more (false).
     */
    fun add(
        handler: suspend (RtcEvent) -> Unit,
        monitors: Collection<ComponentMonitor>,
        wanted: (Boolean) -> Unit,
    ): Subscription {
        val sink = EventSink(core.scope, { true }, Overlap.QUEUE, handler)
        synchronized(sinks) {
            sinks += sink
            monitors.forEach { monitor ->
                monitor.method?.let { sink.offer(WatchMethodChanged(monitor.node, null, it)) }
            }
            if (sinks.size == 1) wanted(true)
        }
        return Subscription {
            synchronized(sinks) {
                if (sinks.remove(sink) && sinks.isEmpty()) wanted(false)
            }
            sink.close()
        }
    }

    /**
     * Records that [monitor] watches its component by [method], telling the reports if that is news, and each of its
     * [registrations] if it is news to them: one told before knows the monitor's last method, one not told yet knows
     * none. Called from the monitor's coroutine, which owns `told`.
     */
    fun announce(monitor: ComponentMonitor, method: WatchMethod, registrations: List<MonitorRegistration>) {
        val old =
            synchronized(sinks) {
                monitor.method.also { previous ->
                    if (previous != method) {
                        monitor.method = method
                        core.model.publish(listOf(WatchMethodChanged(monitor.node, previous, method))) { event ->
                            sinks.forEach { it.offer(event) }
                        }
                    }
                }
            }
        for (registration in registrations) {
            val known = if (registration.told) old else null
            if (known == method) continue
            core.model.publish(listOf(WatchMethodChanged(monitor.node, known, method))) { registration.sink.offer(it) }
            registration.told = true
        }
    }

    /** Ends every report. */
    fun close() {
        sinks.forEach(EventSink::close)
    }
}
