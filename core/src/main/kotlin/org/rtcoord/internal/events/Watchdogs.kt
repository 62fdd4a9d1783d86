package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration
import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job

/**
 * The tree's heartbeat watchdogs: one timer per period runs every check of that period in turn, rather than a timer per
 * watched component (a thousand components watched by push made two thousand timer wake-ups a second). A check only
 * compares the [clock]'s time, read once per tick and handed to every check (10,000 components read it 100,000 times a
 * second otherwise: a third of the tree's samples in a profile), and rarely posts work to its monitor.
 */
internal class Watchdogs(
    private val scope: CoroutineScope,
    private val time: TimeSource,
    private val clock: MillisClock,
) {
    private class Group(val checks: CopyOnWriteArrayList<(now: Long) -> Unit>, val timer: Job)

    private val groups = HashMap<Duration, Group>()

    /** Runs [check] every [period], with the [clock]'s time, until it is [remove]d. */
    fun add(period: Duration, check: (now: Long) -> Unit): Unit =
        synchronized(groups) {
            groups
                .getOrPut(period) {
                    val checks = CopyOnWriteArrayList<(now: Long) -> Unit>()
                    Group(
                        checks,
                        scope.launchTicks(period, time) {
                            val now = clock.now()
                            checks.forEach { it(now) }
                        },
                    )
                }
                .checks += check
        }

    fun remove(period: Duration, check: (now: Long) -> Unit): Unit =
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
