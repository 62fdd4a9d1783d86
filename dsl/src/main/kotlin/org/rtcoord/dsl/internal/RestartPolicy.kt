package org.rtcoord.dsl.internal

import kotlin.time.Duration
import org.rtcoord.dsl.Backoff
import org.rtcoord.dsl.RestartIntensity

/**
 * A supervisor's restart decisions, apart from any I/O so they can be checked on virtual time: the restart intensity
 * over a sliding window, and the back-off of each component's consecutive restarts. A restart is one decision, however
 * many components failed together and are restarted by it. [now] is a monotonic clock.
 */
internal class RestartPolicy(
    private val intensity: RestartIntensity,
    private val backoff: Backoff,
    private val now: () -> Duration,
) {
    /** What to do about a failure. */
    sealed class Decision {
        /** Restart after [wait]: the [attempt]th consecutive restart of that component. */
        data class Restart(val wait: Duration, val attempt: Int) : Decision()

        /** Give up: [restarts] restarts were made within the period already. */
        data class Escalate(val restarts: Int) : Decision()
    }

    /** When each restart within the window was made (or is scheduled to be made). */
    private val restarts = mutableListOf<Duration>()

    /** Per component: how many consecutive restarts, and when the last one was made. */
    private val runs = HashMap<Int, Pair<Int, Duration>>()

    /**
     * Decides about one failure of the components [children] (their indices in the supervisor), failed together now:
     * one restart for all of them, which waits as long as the longest run among them says.
     */
    fun decide(children: Set<Int>): Decision {
        require(children.isNotEmpty()) { "a restart needs at least one component" }
        val time = now()
        restarts.removeAll { time - it >= intensity.period }
        if (restarts.size >= intensity.maxRestarts) return Decision.Escalate(restarts.size)
        val attempt = children.maxOf { child ->
            runs[child]?.takeIf { (_, last) -> time - last < intensity.period }?.first?.plus(1) ?: 1
        }
        val wait = backoff.delay(attempt)
        restarts += time + wait
        children.forEach { runs[it] = attempt to time + wait }
        return Decision.Restart(wait, attempt)
    }
}
