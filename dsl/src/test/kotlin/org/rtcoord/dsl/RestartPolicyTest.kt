package org.rtcoord.dsl

import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.minutes
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.delay
import kotlinx.coroutines.test.currentTime
import kotlinx.coroutines.test.runTest
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.dsl.internal.RestartPolicy
import org.rtcoord.dsl.internal.RestartPolicy.Decision.Escalate
import org.rtcoord.dsl.internal.RestartPolicy.Decision.Restart

/** Restart intensity and back-off, on virtual time: a component failing again as soon as it is restarted. */
class RestartPolicyTest {
    @Test
    fun `consecutive restarts of a component wait twice as long each time, up to the maximum`() = runTest {
        val policy =
            RestartPolicy(RestartIntensity(10, 1.minutes), Backoff.exponential(1.seconds, max = 5.seconds)) {
                currentTime.milliseconds
            }
        val restartedAt = mutableListOf<Long>()
        repeat(5) {
            val decision = policy.decide(setOf(0)) as Restart
            delay(decision.wait)
            restartedAt += currentTime
        }
        assertEquals(listOf(1_000L, 3_000L, 7_000L, 12_000L, 17_000L), restartedAt)

        assertEquals(Restart(1.seconds, 1), policy.decide(setOf(1)), "another component's restarts are its own")
        delay(61.seconds)
        assertEquals(
            Restart(1.seconds, 1),
            policy.decide(setOf(0)),
            "a component quiet for a whole period starts a new run",
        )
    }

    @Test
    fun `more restarts than the intensity within the period escalate, and the window slides`() = runTest {
        val policy = RestartPolicy(RestartIntensity(3, 10.seconds), Backoff.NONE) { currentTime.milliseconds }
        repeat(3) { child ->
            assertEquals(Restart(0.seconds, 1), policy.decide(setOf(child)))
            delay(2.seconds)
        }
        assertEquals(Escalate(3), policy.decide(setOf(0)), "a fourth failure at 6 s")
        delay(4.seconds)
        assertEquals(Restart(0.seconds, 1), policy.decide(setOf(0)), "at 10 s the first restart has left the window")
        assertEquals(Escalate(3), policy.decide(setOf(1)))
    }

    @Test
    fun `restarts count when they are made, after their back-off`() = runTest {
        val policy =
            RestartPolicy(RestartIntensity(1, 10.seconds), Backoff.exponential(8.seconds, max = 8.seconds)) {
                currentTime.milliseconds
            }
        assertEquals(Restart(8.seconds, 1), policy.decide(setOf(0)))
        delay(17.seconds)
        assertEquals(Escalate(1), policy.decide(setOf(0)), "made at 8 s, the restart is still in the window at 17 s")
        delay(1.seconds)
        assertEquals(Restart(8.seconds, 1), policy.decide(setOf(0)))
    }

    @Test
    fun `components failing together are one restart, waiting as long as the longest run among them`() = runTest {
        val policy =
            RestartPolicy(RestartIntensity(1, 10.seconds), Backoff.exponential(1.seconds, max = 4.seconds)) {
                currentTime.milliseconds
            }
        assertEquals(Restart(1.seconds, 1), policy.decide(setOf(0)))
        delay(2.seconds)
        assertEquals(
            Escalate(1),
            policy.decide(setOf(0, 1, 2)),
            "one restart in the window: the intensity counts restarts, not components",
        )
        delay(10.seconds)
        val policyOfThree =
            RestartPolicy(RestartIntensity(2, 10.seconds), Backoff.exponential(1.seconds, max = 4.seconds)) {
                currentTime.milliseconds
            }
        assertEquals(Restart(1.seconds, 1), policyOfThree.decide(setOf(0, 1, 2)), "three lost together: one restart")
        assertEquals(Restart(2.seconds, 2), policyOfThree.decide(setOf(2)), "the second run of component 2")
        assertEquals(Escalate(2), policyOfThree.decide(setOf(1)))
    }

    @Test
    fun `no restart at all escalates at the first failure`() = runTest {
        assertEquals(
            Escalate(0),
            RestartPolicy(RestartIntensity(0, 1.seconds), Backoff.NONE) { currentTime.milliseconds }.decide(setOf(0)),
        )
    }
}
