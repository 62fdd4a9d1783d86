package org.rtcoord.cli

import RTC.LifeCycleState
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.runPeer

/** `find` with each filter, alone and combined. */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class FindCommandTest {
    private val localisation = Localisation()
    private val host = localisation.host
    private val slave = localisation.path("manager.mgr/manager_slave")

    @AfterAll fun stop() = localisation.close()

    private fun find(vararg arguments: String): List<String> =
        runRtcoord("find", host, *arguments).ok().lines().filter { it.isNotEmpty() }

    /**
     * What rtfind finds below the host context, sorted, each component once: rtfind finds a component at its naming
     * path, below the slave that hosts it and again below the master (whose `get_components` includes its slaves');
     * rtcoord names it at its naming path, and below its manager only when its naming path is not among the finds.
     */
    private fun rtfind(vararg arguments: String): List<String> {
        val found =
            runPeer("rtfind", "$host/", *arguments).ok().output.lines().filter {
                it.isNotEmpty() && !it.startsWith("${localisation.path("manager.mgr")}/") || it.startsWith(slave)
            }
        return found
            .filterNot {
                it.startsWith("$slave/") &&
                    it.endsWith(".rtc") &&
                    localisation.path(it.substringAfterLast('/')) in found
            }
            .sorted()
    }

    @Test
    fun `by kind`() {
        assertEquals(listOf(localisation.path("manager.mgr"), slave), find("--type", "manager"))
        assertEquals(listOf(host), find("--type", "context"))
        assertEquals(emptyList<String>(), find("--type", "zombie"))
        assertEquals(4, find("--type", "component").size, "each component once, at its naming path")
    }

    @Test
    fun `names and directories are found as rtfind finds them`() {
        // rtfind searches the whole path for the pattern: no need to write the `.rtc`.
        assertEquals(listOf(localisation.path("laser0.rtc")), find("--name", "laser0"))
        assertEquals(rtfind("-n", "laser0"), find("--name", "laser0").sorted())
        assertEquals(rtfind("-n", "local*0"), find("--name", "local*0").sorted())
        assertEquals(rtfind("-n", "slave"), find("--name", "slave").sorted())
        // rtfind's d: naming contexts, name servers and managers.
        assertEquals(listOf(host, localisation.path("manager.mgr"), slave), find("--type", "directory"))
        assertEquals(rtfind("-t", "d"), find("--type", "directory").sorted())
    }

    @Test
    fun `by name, state and port, combined`() {
        assertEquals(listOf(localisation.path("laser_localise0.rtc")), find("--name", "*local*", "--type", "component"))
        assertEquals(listOf(localisation.path("laser_localise0.rtc")), find("--port", "pose"))
        assertEquals(emptyList<String>(), find("--state", "error"))
        assertEquals(listOf(localisation.path("gyro0.rtc")), find("--state", "active", "--name", "gyro?.rtc"))
    }

    @Test
    fun `rtfind's short options work as in rtfind - -t with its letters, -n, -i and -m`() {
        assertEquals(find("--type", "component"), find("-t", "c"))
        assertEquals(find("--type", "directory"), find("-t", "d"))
        assertEquals(rtfind("-t", "dmn"), find("-t", "dmn").sorted())
        assertEquals(rtfind("-t", "cz"), find("-t", "cz").sorted())
        assertEquals(rtfind("-n", "laser0"), find("-n", "laser0").sorted())
        // Several -n: any may match, as in rtfind.
        assertEquals(rtfind("-n", "laser0", "-n", "gyro0"), find("-n", "laser0", "-n", "gyro0").sorted())
        assertEquals(rtfind("-i", "LASER0"), find("-i", "LASER0").sorted())
        assertEquals(emptyList<String>(), find("-n", "LASER0"))
        // -m counts levels below the start: the context's own entries, not what is below its manager.
        assertEquals(rtfind("-m", "1"), find("-m", "1").sorted())
        assertEquals(rtfind("-m", "1", "-t", "c"), find("-m", "1", "-t", "c").sorted())
        assertEquals(listOf(host), find("-m", "0", "-t", "context"))
        assertTrue("not a type" in runRtcoord("find", host, "-t", "x").usageError())
    }

    @Test
    fun `states are read in any case`() {
        localisation.system.component("gyro0").fail()
        await("gyro0 in ERROR") { localisation.system.component("gyro0").state == LifeCycleState.ERROR_STATE }
        try {
            val inError = listOf(localisation.path("gyro0.rtc"))
            assertEquals(inError, find("--state", "error"))
            assertEquals(inError, find("--state", "ERROR"))
            assertEquals(inError, find("--state", "Error"))
        } finally {
            runRtcoord("reset", localisation.path("gyro0.rtc")).ok()
            runRtcoord("act", localisation.path("gyro0.rtc")).ok()
        }
    }

    @Test
    fun `--json gives paths and kinds`() {
        val json = runRtcoord("--json", "find", host, "--type", "context").ok()
        assertEquals("[\n  {\n    \"path\": \"$host\",\n    \"kind\": \"context\"\n  }\n]\n", json)
    }

    @Test
    fun `with no name server configured, find from the root says so and how to give one, with status 1`() {
        assertEquals(
            "rtcoord: /: no name server configured: give -n HOST[:PORT], or set RTCOORD_NAMESERVERS (or rtshell's RTCTREE_NAMESERVERS), " +
                "e.g. RTCOORD_NAMESERVERS=localhost",
            runRtcoord("find", "/", "-t", "c").failure(),
        )
    }

    @Test
    fun `an unknown state is a usage error`() {
        runRtcoord("find", host, "--state", "sleepy").usageError()
    }
}
