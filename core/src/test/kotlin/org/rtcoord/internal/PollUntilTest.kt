@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.internal

import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.test.runTest
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.rtcoord.InternalRtcoordApi

/** The one poll-until loop, on virtual time: when it calls, what it returns, and when it gives up. */
class PollUntilTest {
    @Test
    fun `the pauses double up to the longest, and the first value is returned`() = runTest {
        val calls = mutableListOf<Long>()
        val found =
            pollUntil(null, 1.milliseconds, 20.milliseconds) {
                calls += testScheduler.currentTime
                calls.size.takeIf { it == 8 }
            }
        assertEquals(8, found)
        assertEquals(listOf(0L, 1, 3, 7, 15, 31, 51, 71), calls)
    }

    @Test
    fun `a condition that holds at once costs one call and no wait`() = runTest {
        var calls = 0
        assertEquals(
            "now",
            pollUntil(testScheduler.timeSource.markNow(), 5.milliseconds) {
                calls++
                "now"
            },
        )
        assertEquals(1, calls)
        assertEquals(0L, testScheduler.currentTime)
    }

    @Test
    fun `past the deadline it gives up after one last call, and says so with null`() = runTest {
        val deadline = testScheduler.timeSource.markNow() + 50.milliseconds
        val calls = mutableListOf<Long>()
        val found =
            pollUntil(deadline, 20.milliseconds) {
                calls += testScheduler.currentTime
                null
            }
        assertNull(found)
        assertEquals(listOf(0L, 20, 40, 60), calls)
    }

    @Test
    fun `an attempt that throws ends the wait with its failure`() = runTest {
        var calls = 0
        val failure =
            assertThrows<IllegalStateException> {
                pollUntil(null, 10.milliseconds) { if (++calls == 3) error("the component went to ERROR") else null }
            }
        assertEquals("the component went to ERROR", failure.message)
        assertEquals(20L, testScheduler.currentTime)
    }
}
