package org.rtcoord

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test
import org.rtcoord.internal.events.ComponentLiveness
import org.rtcoord.internal.events.ComponentLiveness.Change.Finalized
import org.rtcoord.internal.events.ComponentLiveness.Change.Lost
import org.rtcoord.internal.events.ComponentLiveness.Change.Recovered
import org.rtcoord.internal.events.ComponentLiveness.Change.Unreachable
import org.rtcoord.internal.events.ComponentLiveness.State.ANSWERING
import org.rtcoord.internal.events.ComponentLiveness.State.FINALIZED
import org.rtcoord.internal.events.ComponentLiveness.State.SILENT
import org.rtcoord.internal.events.ComponentLiveness.State.UNREACHABLE

/** Whether a component answers, step by step on a clock the test turns (milliseconds). */
class ComponentLivenessTest {
    private val limit = 3_000L

    @Test
    fun `silence past the limit is one loss, and a read that succeeds brings it back`() {
        val liveness = ComponentLiveness(0)
        assertNull(liveness.checked(limit, limit), "exactly the limit is not yet silence")
        assertEquals(Lost(3_500), liveness.checked(3_500, limit))
        assertEquals(SILENT, liveness.state)
        assertNull(liveness.checked(10_000, limit), "the loss is told once")
        assertEquals(listOf(Recovered), liveness.answered(10_100))
        assertEquals(ANSWERING, liveness.state)
        assertEquals(emptyList<ComponentLiveness.Change>(), liveness.answered(10_200), "answering again is no news")
    }

    @Test
    fun `reads that answer are no heartbeats, so a quiet observer is lost at the limit all the same`() {
        val liveness = ComponentLiveness(0)
        assertEquals(emptyList<ComponentLiveness.Change>(), liveness.answered(2_000))
        assertEquals(Lost(3_001), liveness.checked(3_001, limit))
        assertEquals(listOf(Recovered), liveness.answered(3_100))
        assertNull(liveness.checked(6_000, limit), "its silence counts anew from the read that brought it back")
    }

    @Test
    fun `hints keep it alive, and without an observer to hear there is no silence`() {
        val liveness = ComponentLiveness(0)
        liveness.hinted(2_000)
        assertNull(liveness.checked(4_000, limit))
        assertEquals(Lost(3_001), liveness.checked(5_001, limit))
        val unobserved = ComponentLiveness(0)
        assertNull(unobserved.checked(60_000, null))
        assertEquals(ANSWERING, unobserved.state)
    }

    @Test
    fun `a failed call makes it unreachable once, with its silence told if it missed a beat and was not told already`() {
        val answering = ComponentLiveness(0)
        assertEquals(
            listOf(Lost(1_200), Unreachable),
            answering.failed(1_200, gone = false, unreachable = true, beatMillis = 1_000),
        )
        assertEquals(UNREACHABLE, answering.state)
        assertEquals(
            emptyList<ComponentLiveness.Change>(),
            answering.failed(2_000, gone = false, unreachable = true, beatMillis = 1_000),
            "probes that fail are no news",
        )
        assertNull(answering.checked(9_000, limit), "an unreachable component is probed, not watched for silence")

        val silent = ComponentLiveness(0)
        silent.checked(4_000, limit)
        assertEquals(listOf(Unreachable), silent.failed(4_100, gone = false, unreachable = false, beatMillis = 1_000))

        val heard = ComponentLiveness(0)
        heard.hinted(5_000)
        assertEquals(
            listOf(Unreachable),
            heard.failed(5_001, gone = false, unreachable = true, beatMillis = 1_000),
            "no silence of a millisecond",
        )
        assertEquals(
            listOf(Unreachable),
            ComponentLiveness(0).failed(60_000, gone = false, unreachable = true, beatMillis = null),
            "nothing was to be heard",
        )
    }

    @Test
    fun `a hint does not bring back an unreachable component, only a read does`() {
        val liveness = ComponentLiveness(0)
        liveness.failed(100, gone = false, unreachable = true, beatMillis = null)
        liveness.hinted(200)
        assertEquals(UNREACHABLE, liveness.state)
        assertEquals(listOf(Recovered), liveness.answered(300))
    }

    @Test
    fun `an object that no longer exists is finalized, from any state, and stays so`() {
        for (before in
            listOf<(ComponentLiveness) -> Unit>(
                {},
                { it.checked(4_000, limit) },
                { it.failed(4_000, gone = false, unreachable = true, beatMillis = null) },
            )) {
            val liveness = ComponentLiveness(0).also(before)
            assertEquals(listOf(Finalized), liveness.failed(5_000, gone = true, unreachable = true, beatMillis = null))
            assertEquals(FINALIZED, liveness.state)
            assertEquals(emptyList<ComponentLiveness.Change>(), liveness.answered(6_000))
            assertEquals(
                emptyList<ComponentLiveness.Change>(),
                liveness.failed(7_000, gone = true, unreachable = true, beatMillis = null),
            )
        }
    }

    @Test
    fun `once it announced FINALIZE, being unreachable is its end, while answering too late is not`() {
        val liveness = ComponentLiveness(0)
        liveness.hinted(100, finalize = true)
        assertEquals(
            listOf(Unreachable),
            liveness.failed(200, gone = false, unreachable = false, beatMillis = 1_000),
            "a timeout is not an end",
        )
        assertEquals(listOf(Finalized), liveness.failed(300, gone = false, unreachable = true, beatMillis = 1_000))
    }
}
