package org.rtcoord.internal

import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.async
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig

/**
 * A tree faster than the robot's clock (`rtcoord test --speed`): its coroutines' delays, timeouts and timers, and its
 * clock, all run that many times as fast, so what they measure agrees with what they wait.
 */
class TreeSpeedTest {
    @Test
    fun `at a thousand times, a delay of two seconds passes at once, and the tree's clock reads two`() = runBlocking {
        RtcTree(TreeConfig(speed = 1000.0)).use { tree ->
            val host = TimeSource.Monotonic.markNow()
            val robot = tree.core.time.markNow()
            tree.core.scope.async { delay(2.seconds) }.await()
            val onHost = host.elapsedNow()
            // Unscaled, it would take the whole two seconds.
            assertTrue(onHost < 1.seconds, "took $onHost on the host's clock")
            assertTrue(robot.elapsedNow() >= 2.seconds, "the tree's clock read ${robot.elapsedNow()}")
            assertTrue(tree.core.clock.now() >= 2000, "the monitors' clock read ${tree.core.clock.now()} ms")
        }
    }

    @Test
    fun `a timeout in the tree's scope and a timer it sets follow its clock`() = runBlocking {
        RtcTree(TreeConfig(speed = 1000.0)).use { tree ->
            val host = TimeSource.Monotonic.markNow()
            val timedOut = tree.core.scope.async { withTimeoutOrNull(3.seconds) { delay(10.seconds) } }.await()
            assertNull(timedOut)
            val fired = kotlinx.coroutines.CompletableDeferred<Unit>()
            tree.core.at(tree.core.clock.now() + 2000) { fired.complete(Unit) }
            fired.await()
            val onHost = host.elapsedNow()
            assertTrue(onHost < 2.seconds, "took $onHost on the host's clock for 5 s of the tree's")
        }
    }

    @Test
    fun `a speed that is not positive is refused, naming it`() {
        val e = assertThrows<IllegalArgumentException> { TreeConfig(speed = 0.0) }
        assertEquals("speed must be positive, was 0.0", e.message)
        assertThrows<IllegalArgumentException> { TreeConfig.Builder().speed(Double.NaN).build() }
        assertEquals(1.0, TreeConfig().speed)
        RtcTree(TreeConfig()).use { assertTrue(it.core.time === TimeSource.Monotonic) }
    }
}
