package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job

/**
 * The tree's heartbeat watchdogs: one timer per period runs every check of that period in turn, rather than a timer per
 * watched component (a thousand components watched by push made two thousand timer wake-ups a second). A check only
 * compares a time and, rarely, posts work to its monitor.
 */
internal class Watchdogs(private val scope: CoroutineScope, private val time: TimeSource) {
    private class Group(val checks: CopyOnWriteArrayList<() -> Unit>, val timer: Job)

    private val groups = HashMap<Duration, Group>()

    /** Runs [check] every [period] until it is [remove]d. */
    fun add(period: Duration, check: () -> Unit): Unit =
        synchronized(groups) {
            groups
                .getOrPut(period) {
                    val checks = CopyOnWriteArrayList<() -> Unit>()
                    Group(checks, scope.launchTicks(period, time) { checks.forEach { it() } })
                }
                .checks += check
        }

    fun remove(period: Duration, check: () -> Unit): Unit =
        synchronized(groups) {
            val group = groups[period] ?: return
            group.checks -= check
            if (group.checks.isEmpty()) {
                group.timer.cancel()
                groups.remove(period)
            }
        }

    fun close(): Unit =
        synchronized(groups) {
            groups.values.forEach { it.timer.cancel() }
            groups.clear()
        }
}
