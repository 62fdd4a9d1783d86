package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch

/**
 * Calls [tick] every [period] until the returned job is cancelled, at a fixed rate: a tick whose work queues up behind
 * a slow read does not push the next one back. [time] is the clock the scope's delays follow.
 */
internal fun CoroutineScope.launchTicks(period: Duration, time: TimeSource, tick: () -> Unit): Job = launch {
    val start = time.markNow()
    var count = 1L
    while (isActive) {
        delay(period * count.toDouble() - start.elapsedNow())
        count++
        tick()
    }
}
