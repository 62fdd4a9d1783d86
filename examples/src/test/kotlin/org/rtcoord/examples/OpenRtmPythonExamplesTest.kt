package org.rtcoord.examples

import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * OpenRTM-aist-Python's own example components against rtcoord: ConfigSample, whose sets hold values
 * outside its declared constraints, and SequenceOutComponent, whose one-second `on_execute` makes its
 * context answer `RTC_ERROR` to transitions that then happen. Skipped unless `RTCOORD_OPENRTM_PYTHON`
 * names an installation.
 */
class OpenRtmPythonExamplesTest {
    @Test
    fun `ConfigSample - a saved profile restores onto it unchanged, a value written outside its constraint warns, and strict refuses it`(): Unit =
        OpenRtmSystem.start(OpenRtmPython.named()).use { system ->
            startOpenRtmExamples(system)
            OpenRtmConfigurationScenarios.roundTrip(system, "ConfigSample0")
        }

    @Test
    fun `SequenceOutComponent - deactivations behind its one-second on_execute succeed, said to be slow`(): Unit =
        OpenRtmSystem.start(OpenRtmPython.named()).use { system ->
            startOpenRtmExamples(system)
            val outcomes = OpenRtmConfigurationScenarios.deactivations(system, "SequenceOutComponent0")
            // The context answers before on_execute returns only when the call came in its last half second.
            assertTrue(outcomes.any { it.slow && it.lateAnswer == "RTC_ERROR" }, outcomes.toString())
        }

    /**
     * Starts OpenRTM-aist's own ConfigSample (with its `configsample.conf`: sets `mode0` and `mode1` hold
     * values outside its `__constraints__`) and SeqIO's `SequenceOutComponent` (its `on_execute` sleeps
     * 1 s) from the installation's examples, inactive, in a manager of their own.
     */
    private fun startOpenRtmExamples(system: OpenRtmSystem) {
        val examples = (system.installation as OpenRtmPython).examples()
        system.startOwnManager(
            "examples",
            listOf(examples.resolve("ConfigSample"), examples.resolve("SeqIO")),
            listOf("ConfigSample0", "SequenceOutComponent0"),
            "manager.modules.preload: ConfigSample.py, SeqOut.py",
            "manager.components.precreate: ConfigSample, SeqOut",
            "example.ConfigSample.config_file: ${examples.resolve("ConfigSample/configsample.conf")}",
        )
    }
}
