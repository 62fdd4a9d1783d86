package org.rtcoord.dsl

import kotlin.time.Duration

/**
 * How many restarts a supervisor makes within a sliding [period] before it gives up and escalates: `maxRestarts = 3
 * within 60.seconds` allows three, and the fourth failure within a minute escalates.
 *
 * @property maxRestarts how many restarts the window may hold (0: escalate at the first failure).
 * @property period the length of the sliding window.
 */
public class RestartIntensity(public val maxRestarts: Int, public val period: Duration) {
    init {
        require(maxRestarts >= 0) { "maxRestarts must not be negative, was $maxRestarts" }
        require(period.isPositive()) { "the restart period must be positive, was $period" }
    }

    override fun toString(): String = "$maxRestarts within $period"
}
