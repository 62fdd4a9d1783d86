package org.rtcoord.internal

import kotlin.time.Duration
import kotlin.time.TimeMark
import kotlinx.coroutines.delay
import org.rtcoord.InternalRtcoordApi

/**
 * Calls [attempt] until it returns a value, and returns that value; returns null once [deadline] has passed without one
 * (never, when [deadline] is null: the caller's `withTimeout` ends the wait then). Between attempts it waits [pause],
 * then twice as long each time, up to [longestPause]: a condition that holds at once costs one call, one that takes
 * seconds costs a few calls a second. An attempt that throws ends the wait with its failure. The deadline is checked
 * after each attempt, so the last attempt is the first one past it.
 *
 * Public for rtcoord's other modules only (`internal` does not reach across modules).
 */
@InternalRtcoordApi
public suspend fun <T : Any> pollUntil(
    deadline: TimeMark?,
    pause: Duration,
    longestPause: Duration = pause,
    attempt: suspend () -> T?,
): T? {
    require(pause.isPositive() && longestPause >= pause) {
        "a poll's pauses must be positive and grow: $pause to $longestPause"
    }
    var next = pause
    while (true) {
        attempt()?.let {
            return it
        }
        if (deadline?.hasPassedNow() == true) return null
        delay(next)
        next = (next * 2).coerceAtMost(longestPause)
    }
}
