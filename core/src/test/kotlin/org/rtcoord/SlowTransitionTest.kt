package org.rtcoord

import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.rtcoord.java.JavaTree
import org.rtcoord.profile.OrderedAction
import org.rtcoord.profile.SystemProfiles

/**
 * A component whose `on_activated`/`on_deactivated` outlasts its context's transition timeout: the context answers
 * `RTC_ERROR`, and the state arrives later. Within the operation's deadline that is a slow success, for the node's
 * operations and the ordered start and stop built on them.
 */
class SlowTransitionTest {
    private val system = LocalisationSystem()
    private val fixture = system.system.component("laser_localise0")

    @AfterEach fun close() = system.close()

    @Test
    fun `a transition that outlasts the context's timeout succeeds, said to be slow, when the state arrives before the deadline`() =
        runBlocking {
            val localiser = system.tree.component(system.path("laser_localise0.rtc"))
            fixture.slowTransitions(900.milliseconds)
            for (state in listOf(LifeCycle.INACTIVE, LifeCycle.ACTIVE)) {
                val outcome = if (state == LifeCycle.INACTIVE) localiser.deactivate() else localiser.activate()
                assertEquals(state, outcome.state)
                assertEquals("RTC_ERROR", outcome.lateAnswer)
                assertTrue(outcome.slow && outcome.elapsedMillis >= 850, outcome.toString())
                assertEquals(state, localiser.state())
            }
            fixture.slowTransitions(0.milliseconds)
            val prompt = localiser.deactivate()
            assertNull(prompt.lateAnswer, prompt.toString())
        }

    @Test
    fun `Java's transitions, blocking and as futures, return the outcome, slow when it was`() {
        val localiser = JavaTree(system.tree).component(system.path("laser_localise0.rtc"))
        fixture.slowTransitions(900.milliseconds)
        val stopped = localiser.deactivate()
        assertEquals(LifeCycle.INACTIVE, stopped.state)
        assertTrue(stopped.slow, stopped.toString())
        val started = localiser.activateAsync().get(10, TimeUnit.SECONDS)
        assertEquals(LifeCycle.ACTIVE, started.state)
        assertTrue(started.slow, started.toString())
        fixture.slowTransitions(0.milliseconds)
        val prompt = localiser.deactivate()
        assertEquals(LifeCycle.INACTIVE, prompt.state)
        assertFalse(prompt.slow, prompt.toString())
    }

    @Test
    fun `a state that has not arrived by the deadline fails naming the context's answer and the state found`() =
        runBlocking {
            val localiser = system.tree.component(system.path("laser_localise0.rtc"))
            fixture.slowTransitions(2.seconds)
            val failed =
                assertThrows<OperationFailedException> { runBlocking { localiser.deactivate(deadline = 1.seconds) } }
            assertEquals(
                "${localiser.path}: deactivate failed: RTC_ERROR (in context 0; still ACTIVE at its 1000 ms deadline)",
                failed.message,
            )
        }

    @Test
    fun `profile stop and start count a slow step as done and say it was slow`() = runBlocking {
        val profiles = SystemProfiles(system.tree)
        val saved = profiles.save()
        fixture.slowTransitions(900.milliseconds)
        for (action in listOf(OrderedAction.STOP, OrderedAction.START)) {
            val outcomes = profiles.run(saved, action)
            assertTrue(outcomes.all { it.done }, outcomes.joinToString("\n"))
            val slow = outcomes.single { it.step.component.endsWith("/laser_localise0.rtc") }
            assertTrue(slow.detail.startsWith("slow: ") && "RTC_ERROR" in slow.detail, slow.toString())
            assertTrue(outcomes.filter { it !== slow }.all { it.detail.isEmpty() }, outcomes.joinToString("\n"))
        }
    }
}
