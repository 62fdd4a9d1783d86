package org.rtcoord.cli

import RTC.LifeCycleState
import kotlin.time.Duration.Companion.milliseconds
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.Behaviour
import org.rtcoord.runtime.ComponentContext
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.rtSystem

/** `act`, `deact` and `reset`: they wait for the state, check everything first and report return codes. */
class LifecycleCommandTest {
    private val localisation = Localisation()

    @AfterEach fun stop() = localisation.close()

    private fun state(instance: String): LifeCycleState = localisation.system.component(instance).state

    @Test
    fun `deact and act wait until the state is reached`() {
        runRtcoord("deact", localisation.path("laser0.rtc"), localisation.path("gyro0.rtc")).ok()
        assertEquals(LifeCycleState.INACTIVE_STATE, state("laser0"))
        assertEquals(LifeCycleState.INACTIVE_STATE, state("gyro0"))
        runRtcoord("act", localisation.path("laser0.rtc"), localisation.path("gyro0.rtc")).ok()
        assertEquals(LifeCycleState.ACTIVE_STATE, state("laser0"))
        assertEquals(LifeCycleState.ACTIVE_STATE, state("gyro0"))
    }

    @Test
    fun `a component already in the target state is left as it is`() {
        assertEquals("", runRtcoord("act", localisation.path("laser0.rtc")).ok())
        assertEquals(LifeCycleState.ACTIVE_STATE, state("laser0"))
    }

    @Test
    fun `reset brings a component out of ERROR`() {
        localisation.system.component("gyro0").fail()
        await("gyro0 in ERROR") { state("gyro0") == LifeCycleState.ERROR_STATE }
        runRtcoord("reset", localisation.path("gyro0.rtc")).ok()
        assertEquals(LifeCycleState.INACTIVE_STATE, state("gyro0"))
    }

    @Test
    fun `a port path is refused as not a component, by every lifecycle command and exit`() {
        val port = localisation.path("laser0.rtc:laser")
        for (command in listOf("act", "deact", "reset", "exit")) {
            assertEquals("rtcoord: $port: is a port, not a component", runRtcoord(command, port).failure(), command)
        }
        assertEquals(LifeCycleState.ACTIVE_STATE, state("laser0"))
        assertEquals(false, localisation.system.component("laser0").isExited)
    }

    @Test
    fun `one bad path among good ones changes nothing`() {
        val line =
            runRtcoord(
                    "deact",
                    localisation.path("laser0.rtc"),
                    localisation.path("sonar0.rtc"),
                    localisation.path("gyro0.rtc"),
                )
                .failure()
        assertEquals("rtcoord: ${localisation.path("sonar0.rtc")}: not found", line)
        assertEquals(LifeCycleState.ACTIVE_STATE, state("laser0"))
        assertEquals(LifeCycleState.ACTIVE_STATE, state("gyro0"))
    }

    @Test
    fun `one component in the wrong state among good ones changes nothing and names the return code`() {
        localisation.system.component("gyro0").fail()
        await("gyro0 in ERROR") { state("gyro0") == LifeCycleState.ERROR_STATE }
        val line = runRtcoord("deact", localisation.path("laser0.rtc"), localisation.path("gyro0.rtc")).failure()
        assertEquals(
            "rtcoord: ${localisation.path("gyro0.rtc")}: deactivate refused: the component is ERROR in context 0, not ACTIVE (PRECONDITION_NOT_MET)",
            line,
        )
        assertEquals(LifeCycleState.ACTIVE_STATE, state("laser0"))
    }

    @Test
    fun `a component that refuses to activate fails the command with its return code`() {
        val stubborn = ComponentType("stubborn", behaviour = { Refusing })
        rtSystem(localisation.naming.corbaloc) { component(stubborn) }
            .use {
                val line = runRtcoord("act", localisation.path("stubborn0.rtc")).failure()
                assertEquals(
                    "rtcoord: ${localisation.path("stubborn0.rtc")}: activate failed: RTC_ERROR (the component went to ERROR in context 0)",
                    line,
                )
            }
    }

    @Test
    fun `a transition that outlasts the context's transition timeout succeeds, and one line says it was slow`() {
        localisation.system.component("laser_localise0").slowTransitions(900.milliseconds)
        val localiser = localisation.path("laser_localise0.rtc")
        for ((command, done, state) in
            listOf(Triple("deact", "deactivated", "INACTIVE"), Triple("act", "activated", "ACTIVE"))) {
            val line = runRtcoord(command, localiser).ok()
            val slow =
                Regex(
                    """\Q$localiser\E: $done slowly: its context answered RTC_ERROR once its transition timeout passed, $state after \d+ ms\n"""
                )
            assertTrue(slow.matches(line), line)
        }
        assertEquals(LifeCycleState.ACTIVE_STATE, state("laser_localise0"))
    }

    @Test
    fun `the execution context is chosen by handle or by index, not both`() {
        runRtcoord("deact", "--index", "0", localisation.path("laser0.rtc")).ok()
        assertEquals(LifeCycleState.INACTIVE_STATE, state("laser0"))
        runRtcoord("act", "--context", "0", localisation.path("laser0.rtc")).ok()
        assertEquals(LifeCycleState.ACTIVE_STATE, state("laser0"))
        val line = runRtcoord("deact", "--context", "1000", localisation.path("laser0.rtc")).failure()
        assertEquals(
            "rtcoord: ${localisation.path("laser0.rtc")}: no execution context with handle 1000 (handles: 0)",
            line,
        )
        runRtcoord("act", "--context", "0", "--index", "0", localisation.path("laser0.rtc")).usageError()
        runRtcoord("act").usageError()
    }

    /** A behaviour whose activation always fails, as a component that cannot open its device does. */
    private object Refusing : Behaviour {
        override fun onActivated(rtc: ComponentContext): Boolean = false
    }
}
