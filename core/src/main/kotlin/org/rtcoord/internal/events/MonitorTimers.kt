package org.rtcoord.internal.events

import org.rtcoord.internal.TreeCore
import kotlin.time.Duration

/**
 * The timers of one component's monitor: its [member]ship of the tree's poll schedule, and the watchdog
 * of its observer's heartbeats, which only posts work to the monitor ([check], a liveness check). A sign
 * of life (a heartbeat, a poll read that found nothing new) only records when it came ([heard]), on the
 * ORB's thread, and wakes the monitor only once a beat is overdue.
 */
internal class MonitorTimers(private val core: TreeCore, private val member: PollSchedule.Member, private val check: () -> Unit) {
    /** The period it is polled at, or null. */
    var pollPeriod: Duration? = null
        private set

    private var watchdog: Pair<Duration, () -> Unit>? = null

    /** When the last sign of life came, in [now]'s milliseconds. */
    @Volatile var heardAt: Long = now()
        private set

    fun heard() {
        heardAt = now()
    }

    /** Polls the component every [period], or no more when null. */
    fun poll(period: Duration?) {
        if (period == pollPeriod) return
        pollPeriod?.let { core.watcher.unpoll(it, member) }
        pollPeriod = period
        period?.let { core.watcher.poll(it, member) }
    }

    /** Checks, every half [heartbeat], whether a beat is overdue; no more when null. */
    fun watch(heartbeat: Duration?) {
        watchdog?.let { (period, overdue) -> core.watcher.watchdogs.remove(period, overdue) }
        watchdog = heartbeat?.let {
            val beat = it.inWholeMilliseconds
            val overdue = { if (now() - heardAt >= beat) check() }
            core.watcher.watchdogs.add(it / 2, overdue)
            it / 2 to overdue
        }
    }

    fun stop() {
        poll(null)
        watch(null)
    }

    companion object {
        /** Milliseconds of the monotonic clock every monitor uses. */
        fun now(): Long = System.nanoTime() / 1_000_000
    }
}
