package org.rtcoord.internal.events

import kotlin.time.Duration
import org.rtcoord.internal.TreeCore

/**
 * The timers of one component's monitor: its membership of the tree's poll schedule, and the watchdog of its observer's
 * heartbeats, which only posts work to the monitor ([check], a liveness check, with when the last sign of life came). A
 * sign of life (a heartbeat, a poll read that found nothing new) only records when it came ([heard]), on the ORB's
 * thread, and wakes the monitor only once a beat is overdue.
 */
internal class MonitorTimers(
    private val core: TreeCore,
    private val probe: StateProbe?,
    private val clock: MillisClock,
    private val tick: (done: () -> Unit) -> Unit,
    private val check: (heardAt: Long) -> Unit,
) {
    /** Its place in the poll schedule: a tick is sent as a [probe] when it can go without the monitor. */
    private val member =
        object : PollSchedule.Member {
            override fun tick(done: () -> Unit) = this@MonitorTimers.tick(done)

            override fun probe(done: () -> Unit): Boolean = probe?.send(done) ?: false

            override fun late() {
                probe?.late()
            }
        }

    /** The period it is polled at, or null. */
    private var pollPeriod: Duration? = null

    private var watchdog: Pair<Duration, (Long) -> Unit>? = null

    /** When the last sign of life came, in the [clock]'s milliseconds. */
    @Volatile private var heardAt: Long = clock.now()

    /** A sign of life came just now. */
    fun heard() {
        heardAt = clock.now()
    }

    /** Polls the component every [period], or no more when null. */
    fun poll(period: Duration?) {
        if (period == pollPeriod) return
        pollPeriod?.let { core.watcher.polls.remove(it, member) }
        pollPeriod = period
        period?.let { core.watcher.polls.add(it, member) }
    }

    /**
     * Checks, every tenth of [heartbeat], whether a beat is overdue; no more when null. A check costs a comparison, and
     * a process that died is found out within a tenth of a beat of its beat being overdue.
     */
    fun watch(heartbeat: Duration?) {
        watchdog?.let { (period, overdue) -> core.watcher.watchdogs.remove(period, overdue) }
        watchdog = heartbeat?.let {
            val beat = it.inWholeMilliseconds
            val overdue = { now: Long -> if (now - heardAt >= beat) check(heardAt) }
            core.watcher.watchdogs.add(it / CHECKS_PER_BEAT, overdue)
            it / CHECKS_PER_BEAT to overdue
        }
    }

    fun stop() {
        poll(null)
        watch(null)
    }

    private companion object {
        const val CHECKS_PER_BEAT = 10
    }
}
