package org.rtcoord.internal.events

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test

/** How an FSM_STATUS hint is read. */
class HintTest {
    @Test
    fun `an FSM_STATUS hint tells the state entered once its entry action ran`() {
        assertEquals("Cooking", Hint(HintKind.FSM_STATUS, "Cooking POST_ONENTRY").fsmEntered())
        assertEquals(
            "Idle",
            Hint(HintKind.FSM_STATUS, " Idle  post_onentry ").fsmEntered(),
            "read leniently, as every hint",
        )
        assertNull(Hint(HintKind.FSM_STATUS, "Cooking PRE_ONENTRY").fsmEntered())
        assertNull(Hint(HintKind.FSM_STATUS, "Programmed POST_ON_STATE_CHNAGE").fsmEntered())
        assertNull(Hint(HintKind.OTHER, "Cooking POST_ONENTRY").fsmEntered())
        assertEquals(HintKind.FSM_STATUS, Hint.omg(RTC.StatusKind.FSM_STATUS, "Idle POST_ONENTRY").kind)
        assertEquals(HintKind.OTHER, Hint.omg(RTC.StatusKind.FSM_STRUCTURE, "").kind)
    }
}
