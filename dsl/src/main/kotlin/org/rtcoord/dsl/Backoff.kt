package org.rtcoord.dsl

import kotlin.time.Duration

/**
 * How long a supervisor waits before restarting a component that keeps failing: the first restart of a run waits
 * [initial], each consecutive one [factor] times longer, never more than [max]. Restarts are consecutive while each
 * failure comes within the supervisor's restart period of the previous restart.
 *
 * @property initial the wait before the first restart of a run.
 * @property max the longest wait.
 * @property factor how much longer each consecutive wait is.
 */
public class Backoff
private constructor(
    public val initial: Duration,
    public val max: Duration,
    public val factor: Double,
) {
    /** The wait before the [attempt]th consecutive restart (1 for the first). */
    public fun delay(attempt: Int): Duration {
        require(attempt >= 1) { "attempts count from 1, was $attempt" }
        var wait = initial
        repeat(attempt - 1) { wait = (wait * factor).coerceAtMost(max) }
        return wait.coerceAtMost(max)
    }

    override fun toString(): String = if (max == Duration.ZERO) "immediately" else "exponential from $initial to $max"

    public companion object {
        /** No wait: restart at once. */
        public val NONE: Backoff = Backoff(Duration.ZERO, Duration.ZERO, 1.0)

        /** Waits [initial], then [factor] times longer for each consecutive restart, up to [max]. */
        public fun exponential(initial: Duration, max: Duration, factor: Double = 2.0): Backoff {
            require(initial.isPositive()) { "the initial back-off must be positive, was $initial" }
            require(max >= initial) { "the maximum back-off ($max) must not be below the initial one ($initial)" }
            require(factor >= 1.0) { "the back-off factor must be at least 1, was $factor" }
            return Backoff(initial, max, factor)
        }
    }
}
