package org.rtcoord.internal.events

import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.TimeSource

/**
 * Milliseconds of one monotonic [time] source, counted from the clock's making: the `now` every component monitor and
 * its timers use, which tests replace with a source they turn by hand.
 */
internal class MillisClock(time: TimeSource = TimeSource.Monotonic) {
    private val origin = time.markNow()

    /** Milliseconds since the clock was made. */
    fun now(): Long = origin.elapsedNow().inWholeMilliseconds

    /** Nanoseconds until the clock reads [millis]: a timer armed for that long finds [now] at [millis] or past it. */
    fun nanosUntil(millis: Long): Long = (millis.milliseconds - origin.elapsedNow()).inWholeNanoseconds.coerceAtLeast(0)
}
