package org.rtcoord.internal.events

import kotlin.time.TimeSource

/**
 * Milliseconds of one monotonic [time] source, counted from the clock's making: the `now` every
 * component monitor and its timers use, which tests replace with a source they turn by hand.
 */
internal class MillisClock(time: TimeSource = TimeSource.Monotonic) {
    private val origin = time.markNow()

    /** Milliseconds since the clock was made. */
    fun now(): Long = origin.elapsedNow().inWholeMilliseconds
}
