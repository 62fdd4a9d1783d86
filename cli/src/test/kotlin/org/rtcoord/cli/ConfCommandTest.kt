package org.rtcoord.cli

import _SDOPackage.ConfigurationSet
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await

/** `conf`: list, get, set and act, read back from the component itself. */
class ConfCommandTest {
    private val localisation = Localisation()
    private val localiser = localisation.path("laser_localise0.rtc")
    private val fixture = localisation.system.component("laser_localise0")

    @AfterEach fun stop() = localisation.close()

    @Test
    fun `lists the sets, the active one marked, hidden ones only with --all`() {
        val sets = "* default\n    fail  0\n    gain  1.0\n  precise\n    fail  0\n    gain  0.5\n"
        assertEquals(sets, runRtcoord("conf", localiser).ok())
        assertEquals(sets, runRtcoord("conf", localiser, "list").ok())
        assertEquals("  __constraints__\n    gain  0<x<10\n$sets", runRtcoord("conf", localiser, "list", "--all").ok())
        assertEquals(
            "  precise\n    fail  0\n    gain  0.5\n",
            runRtcoord("conf", localiser, "list", "--set", "precise").ok(),
        )
        assertEquals(
            "{\n  \"active\": \"default\",\n  \"sets\": {\n    \"precise\": {\n      \"fail\": \"0\",\n      \"gain\": \"0.5\"\n    }\n  }\n}\n",
            runRtcoord("--json", "conf", localiser, "list", "--set", "precise").ok(),
        )
    }

    @Test
    fun `gets and sets a value in the active set or another`() {
        assertEquals("1.0\n", runRtcoord("conf", localiser, "get", "gain").ok())
        runRtcoord("conf", localiser, "set", "gain", "2.5").ok()
        assertEquals("default", fixture.activeConfigurationSet)
        await("the component to use gain 2.5") { fixture.parameter("gain") == "2.5" }
        assertEquals("2.5\n", runRtcoord("conf", localiser, "get", "gain").ok())
        runRtcoord("conf", localiser, "set", "gain", "0.25", "--set", "precise").ok()
        assertEquals("0.25\n", runRtcoord("conf", localiser, "get", "gain", "--set", "precise").ok())
        assertEquals("default", fixture.activeConfigurationSet, "writing another set keeps the active one")
        assertEquals("2.5", fixture.parameter("gain"))
    }

    @Test
    fun `a component with no active set is listed with none marked, and act or set --set repairs it`() {
        val configuration = fixture.ref.get_configuration()
        // A set added through CORBA, as any tool may: OpenRTM-aist then has no set active.
        assertTrue(configuration.add_configuration_set(ConfigurationSet("night", "", emptyArray())))
        val listed = runRtcoord("conf", localiser)
        assertEquals(0, listed.statusCode, listed.stderr)
        assertEquals(
            "  default\n    fail  0\n    gain  1.0\n  night\n  precise\n    fail  0\n    gain  0.5\n",
            listed.stdout,
        )
        assertEquals(
            "rtcoord: $localiser: no configuration set is active; 'rtcoord conf $localiser act SET' activates one\n",
            listed.stderr,
        )
        assertTrue(runRtcoord("--json", "conf", localiser, "list").stdout.contains("\"active\": null"))
        val sets = "sets: __constraints__, default, night, precise"
        assertEquals(
            "rtcoord: $localiser: get gain refused: no configuration set is active: name one with --set, or activate one ($sets)",
            runRtcoord("conf", localiser, "get", "gain").failure(),
        )
        assertEquals(
            "rtcoord: $localiser: set gain refused: no configuration set is active: name the set to change ($sets)",
            runRtcoord("conf", localiser, "set", "gain", "2.0").failure(),
        )

        runRtcoord("conf", localiser, "set", "gain", "0.75", "--set", "precise").ok()
        assertEquals("precise", fixture.activeConfigurationSet)
        await("the component to use gain 0.75") { fixture.parameter("gain") == "0.75" }

        assertTrue(configuration.add_configuration_set(ConfigurationSet("dusk", "", emptyArray())))
        runRtcoord("conf", localiser, "act", "default").ok()
        assertEquals("default", fixture.activeConfigurationSet)
        await("the component to use gain 1.0") { fixture.parameter("gain") == "1.0" }
    }

    @Test
    fun `activates a set`() {
        runRtcoord("conf", localiser, "act", "precise").ok()
        assertEquals("precise", fixture.activeConfigurationSet)
        await("the component to use gain 0.5") { fixture.parameter("gain") == "0.5" }
    }

    @Test
    fun `a value outside the declared constraint is written with a warning, as OpenRTM-aist writes it, and --strict refuses it`() {
        val line = runRtcoord("conf", localiser, "set", "--strict", "gain", "42").failure()
        assertEquals("rtcoord: $localiser: set gain rejected: '42' is outside 0<x<10", line)
        assertEquals("1.0", fixture.parameter("gain"))

        val written = runRtcoord("conf", localiser, "set", "gain", "42")
        assertEquals(0, written.statusCode, written.stderr)
        assertEquals(
            "rtcoord: warning: $localiser: gain: '42' is outside 0<x<10 (written: OpenRTM-aist does not check constraints)\n",
            written.stderr,
        )
        await("the component to use gain 42") { fixture.parameter("gain") == "42" }
    }

    @Test
    fun `unknown parameters, sets and actions are named`() {
        assertEquals(
            "rtcoord: $localiser: no parameter 'speed' in configuration set 'default' (parameters: fail, gain)",
            runRtcoord("conf", localiser, "get", "speed").failure(),
        )
        assertEquals(
            "rtcoord: $localiser: no configuration set 'fast' (sets: __constraints__, default, precise)",
            runRtcoord("conf", localiser, "act", "fast").failure(),
        )
        runRtcoord("conf", localiser, "toggle").usageError()
    }
}
