package org.rtcoord

import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows

class EventOptionsTest {
    private val options = EventOptions(WatchMode.PUSH, 250.milliseconds, Overlap.LATEST, 2.seconds, 5, 300.milliseconds)

    private fun fields(o: EventOptions) =
        listOf(o.mode, o.pollPeriod, o.overlap, o.heartbeat, o.missedBeats, o.trafficInterval)

    @Test
    fun `newBuilder keeps every field it is not told to change`() {
        assertEquals(fields(options), fields(options.newBuilder().build()))
        val queued = options.newBuilder().overlap(Overlap.QUEUE).build()
        assertEquals(
            listOf(WatchMode.PUSH, 250.milliseconds, Overlap.QUEUE, 2.seconds, 5, 300.milliseconds),
            fields(queued),
        )
    }

    @Test
    fun `the builder starts from the defaults and checks what it builds as the constructor does`() {
        assertEquals(fields(EventOptions()), fields(EventOptions.Builder().build()))
        val e = assertThrows<IllegalArgumentException> { EventOptions.Builder().missedBeats(0).build() }
        assertEquals("missedBeats must be positive, was 0", e.message)
    }
}
