package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

class HeartbeatBudgetTest {
    @Test
    fun `observers beat as asked up to the budget, and past it at the power of two seconds that keeps under it`() {
        assertEquals(Duration.ZERO, HeartbeatBudget.floorFor(1))
        assertEquals(Duration.ZERO, HeartbeatBudget.floorFor(2500))
        assertEquals(2.seconds, HeartbeatBudget.floorFor(2501))
        assertEquals(2.seconds, HeartbeatBudget.floorFor(5000))
        assertEquals(4.seconds, HeartbeatBudget.floorFor(10_000))
        assertEquals(8.seconds, HeartbeatBudget.floorFor(10_001))
        for (count in listOf(2501, 4000, 7777, 10_000, 50_000, 1_000_000)) {
            val floor = HeartbeatBudget.floorFor(count)
            val beats = count / floor.inWholeMilliseconds.toDouble() * 1000
            assertTrue(beats <= HeartbeatBudget.BEATS_PER_SECOND, "$count components at $floor: $beats a second")
            assertTrue(
                beats > HeartbeatBudget.BEATS_PER_SECOND / 2,
                "$count components at $floor: no longer than needed",
            )
        }
    }

    @Test
    fun `a change of the floor is told once, and none while it stays`() {
        var told = 0
        val budget = HeartbeatBudget { told++ }
        (1..2500).forEach(budget::watching)
        assertEquals(0, told)
        budget.watching(2501)
        budget.watching(3000)
        assertEquals(1, told)
        assertEquals(2.seconds, budget.floor)
        budget.watching(2500)
        assertEquals(2, told, "fewer components: observers beat as asked again")
        assertEquals(Duration.ZERO, budget.floor)
    }
}
