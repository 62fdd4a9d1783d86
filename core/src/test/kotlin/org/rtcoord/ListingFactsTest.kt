package org.rtcoord

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/** The facts tools show of a listing, worked out once in core: overall state, kind labels, dead objects. */
class ListingFactsTest {
    private fun overall(vararg states: LifeCycle) =
        ComponentSummary(states.withIndex().associate { (handle, state) -> handle to state }, emptyList()).overallState

    @Test
    fun `the overall state puts ERROR over ACTIVE over INACTIVE, else CREATED, and UNKNOWN without contexts`() {
        assertEquals(LifeCycle.ERROR, overall(LifeCycle.ACTIVE, LifeCycle.ERROR, LifeCycle.INACTIVE))
        assertEquals(LifeCycle.ACTIVE, overall(LifeCycle.INACTIVE, LifeCycle.ACTIVE))
        assertEquals(LifeCycle.INACTIVE, overall(LifeCycle.CREATED, LifeCycle.INACTIVE))
        assertEquals(LifeCycle.CREATED, overall(LifeCycle.CREATED, LifeCycle.UNKNOWN))
        assertEquals(LifeCycle.UNKNOWN, overall())
    }

    @Test
    fun `kinds read as words`() {
        assertEquals("name server", NodeKind.NAME_SERVER.label)
        assertEquals("component", NodeKind.COMPONENT.label)
    }

    @Test
    fun `an unreachable or hung object is taken for dead, a refused operation is not`() {
        assertTrue(UnreachableException("/ns/a.rtc", RuntimeException("COMM_FAILURE")).meansDead)
        assertTrue(TimedOutException("/ns/a.rtc", "get_owned_contexts", 5_000).meansDead)
        assertFalse(PreconditionNotMetException("/ns/a.rtc", "activate", "ACTIVE").meansDead)
        assertFalse(NotFoundException("/ns/a.rtc").meansDead)
    }
}
