package org.rtcoord.dsl

import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.Overlap
import org.rtcoord.WatchMode
import org.rtcoord.dsl.internal.queued

/** A subscription shared by several rules queues every event, and watches as the rules asked otherwise. */
class QueuedOptionsTest {
    @Test
    fun `the shared subscription's options keep every field but the overlap, the traffic interval too`() {
        val asked = EventOptions(WatchMode.POLL, 200.milliseconds, Overlap.SKIP, 2.seconds, 4, 50.milliseconds)
        val shared = asked.queued()
        assertEquals(Overlap.QUEUE, shared.overlap)
        assertEquals(
            listOf(asked.mode, asked.pollPeriod, asked.heartbeat, asked.missedBeats, asked.trafficInterval),
            listOf(shared.mode, shared.pollPeriod, shared.heartbeat, shared.missedBeats, shared.trafficInterval),
        )
    }
}
