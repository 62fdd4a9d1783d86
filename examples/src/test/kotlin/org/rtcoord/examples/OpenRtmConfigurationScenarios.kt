package org.rtcoord.examples

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.assertThrows
import org.rtcoord.LifeCycle
import org.rtcoord.TransitionOutcome
import org.rtcoord.profile.ProfileRefusedException
import org.rtcoord.profile.SystemProfiles

/**
 * What real OpenRTM-aist components with awkward configurations and callbacks must get from rtcoord, for
 * [OpenRtmPythonExamplesTest] (OpenRTM-aist-Python's own examples) and [OpenRtmCppTest] (ours in C++).
 */
object OpenRtmConfigurationScenarios {
    /**
     * [instance] ships `int_param0` = 12345 in its set `mode0` while it declares `0<=x<=150`: a saved profile restores
     * onto it unchanged, a value written outside the constraint warns, and strict refuses it.
     */
    fun roundTrip(system: OpenRtmSystem, instance: String): Unit = runBlocking {
        val profiles = SystemProfiles(system.witness)
        val sample = system.witness.component(system.path("$instance.rtc"))
        val saved =
            profiles.save().let { all ->
                all.withComponents(all.components.filter { it.instanceName == instance })
                    .withDataPortConnectors(emptyList())
                    .withServicePortConnectors(emptyList())
            }
        assertEquals(
            "12345",
            saved.components.single().configurationSet("mode0")!!.data["int_param0"],
            "the value mode0 ships",
        )

        val unchanged = profiles.restore(saved, strict = true)
        assertEquals(emptyList<String>(), unchanged.done + unchanged.warnings)

        sample.setParameter("int_param0", "100", "mode0")
        val outside = "${sample.path}: configuration set 'mode0': int_param0: '12345' is outside 0<=x<=150"
        assertEquals(
            outside,
            assertThrows<ProfileRefusedException> { runBlocking { profiles.restore(saved, strict = true) } }.reason,
        )
        assertEquals(
            "100",
            sample.configuration().sets.getValue("mode0")["int_param0"],
            "the strict restore wrote nothing",
        )
        val restored = profiles.restore(saved)
        assertEquals(listOf(outside), restored.warnings)
        assertEquals("12345", sample.configuration().sets.getValue("mode0")["int_param0"])
    }

    /**
     * Activates and deactivates [instance] [times] times: every deactivation ends INACTIVE, whatever the context
     * answered. Returns the deactivations' outcomes.
     */
    fun deactivations(system: OpenRtmSystem, instance: String, times: Int = 4): List<TransitionOutcome> = runBlocking {
        val component = system.witness.component(system.path("$instance.rtc"))
        val outcomes =
            (1..times).map {
                component.activate()
                component.deactivate().also { println("${system.installation.label}: $instance deactivated: $it") }
            }
        assertTrue(outcomes.all { it.state == LifeCycle.INACTIVE }, outcomes.toString())
        assertEquals(LifeCycle.INACTIVE, component.state())
        outcomes
    }
}
