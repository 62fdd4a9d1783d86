package org.rtcoord.cli

import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test

/**
 * What the commands that run until stopped wait on (`watch`, `run`, `print`...); its threads are checked on the jar, in
 * CliJarIT.
 */
class StopSignalsTest {
    @Test
    fun `a limited wait with no stop ends when its time is up, with no reason`(): Unit = runBlocking {
        StopSignals().use { signals -> assertNull(signals.await(100.milliseconds)) }
    }

    @Test
    fun `a stop ends a limited wait at once with its reason`(): Unit = runBlocking {
        StopSignals().use { signals ->
            launch { signals.stop("SIGTERM") }
            assertEquals("SIGTERM", signals.await(1.hours))
        }
    }
}
