package org.rtcoord.dsl

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.dsl.internal.DataLiveness
import org.rtcoord.dsl.internal.DataLiveness.Finding

/** The silence and rate watchdog of data rules, on plain numbers for time. */
class DataLivenessTest {
    @Test
    fun `silence is reported once per silence, only after the limit, and a sample re-arms it`() {
        val liveness = DataLiveness(silenceMillis = 500, minRate = null).apply { tapped(0) }
        liveness.sample(100)
        assertEquals(Finding.NOTHING, liveness.check(599, active = true))
        assertEquals(Finding.Silent(500), liveness.check(600, active = true))
        assertEquals(Finding.NOTHING, liveness.check(900, active = true), "once per silence")
        liveness.sample(950)
        assertEquals(Finding.NOTHING, liveness.check(1400, active = true))
        assertEquals(Finding.Silent(500), liveness.check(1450, active = true), "the sample re-armed it")
    }

    @Test
    fun `time while the component is not ACTIVE does not count`() {
        val liveness = DataLiveness(silenceMillis = 500, minRate = null).apply { tapped(0) }
        assertEquals(Finding.NOTHING, liveness.check(2000, active = false))
        assertEquals(
            Finding.NOTHING,
            liveness.check(2400, active = true),
            "silence counts from when it was seen ACTIVE",
        )
        assertEquals(Finding.Silent(500), liveness.check(2500, active = true))
    }

    @Test
    fun `a rate below the floor over the last second is reported once, after a full window, and re-armed when it recovers`() {
        val liveness = DataLiveness(silenceMillis = null, minRate = 5.0).apply { tapped(0) }
        for (t in 0L until 1000L step 100) liveness.sample(t)
        assertEquals(Finding.NOTHING, liveness.check(999, active = true), "ten a second")
        for (t in 1000L until 2000L step 500) liveness.sample(t)
        assertEquals(Finding.Slow(2.0), liveness.check(1999, active = true))
        assertEquals(Finding.NOTHING, liveness.check(2050, active = true), "once per drop")
        for (t in 2100L until 3100L step 100) liveness.sample(t)
        assertEquals(Finding.NOTHING, liveness.check(3050, active = true), "back at its floor")
        assertEquals(Finding.Slow(0.0), liveness.check(4100, active = true), "re-armed")
    }

    @Test
    fun `nothing counts before the port is tapped, and silence counts from each tap`() {
        val liveness = DataLiveness(silenceMillis = 500, minRate = 5.0)
        assertEquals(Finding.NOTHING, liveness.check(3000, active = true), "not tapped yet: nothing can arrive")
        liveness.tapped(3000)
        assertEquals(Finding.NOTHING, liveness.check(3499, active = true))
        assertEquals(Finding.Silent(500), liveness.check(3500, active = true))
        liveness.tapped(4000)
        assertEquals(Finding.NOTHING, liveness.check(4499, active = true), "tapped again: counted anew")
        assertEquals(Finding.Silent(500), liveness.check(4500, active = true))
        assertEquals(
            Finding.Slow(0.0),
            liveness.check(5000, active = true),
            "the rate over a full window since the tap",
        )
    }
}
