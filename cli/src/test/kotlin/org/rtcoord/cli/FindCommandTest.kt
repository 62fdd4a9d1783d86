package org.rtcoord.cli

import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.rtcoord.fixtures.runPeer

/** `find` with each filter, alone and combined. */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class FindCommandTest {
    private val localisation = Localisation()
    private val host = localisation.host
    private val slave = localisation.path("manager.mgr/manager_slave")

    @AfterAll
    fun stop() = localisation.close()

    private fun find(vararg arguments: String): List<String> = runRtcoord("find", host, *arguments).ok().lines().filter { it.isNotEmpty() }

    @Test
    fun `by kind`() {
        assertEquals(listOf(localisation.path("manager.mgr"), slave), find("--type", "manager"))
        assertEquals(listOf(host), find("--type", "context"))
        assertEquals(emptyList<String>(), find("--type", "zombie"))
        assertEquals(8, find("--type", "component").size, "each component below its context and below its manager")
    }

    @Test
    fun `names and directories are found as rtfind finds them`() {
        val master = localisation.path("manager.mgr")
        // A master lists its slaves' components with its own; rtfind finds them below both, rtcoord below the slave.
        fun rtfind(vararg arguments: String) = runPeer("rtfind", "$host/", *arguments).ok().output.lines()
            .filter { it.isNotEmpty() && !(it.startsWith("$master/") && it.endsWith(".rtc") && '/' !in it.removePrefix("$master/")) }.sorted()
        // rtfind searches the whole path for the pattern: no need to write the `.rtc`.
        assertEquals(listOf("$slave/laser0.rtc", localisation.path("laser0.rtc")), find("--name", "laser0"))
        assertEquals(rtfind("-n", "laser0"), find("--name", "laser0").sorted())
        assertEquals(rtfind("-n", "local*0"), find("--name", "local*0").sorted())
        assertEquals(rtfind("-n", "slave"), find("--name", "slave").sorted())
        // rtfind's d: naming contexts, name servers and managers.
        assertEquals(listOf(host, localisation.path("manager.mgr"), slave), find("--type", "directory"))
        assertEquals(rtfind("-t", "d"), find("--type", "directory").sorted())
    }

    @Test
    fun `by name, state and port, combined`() {
        assertEquals(listOf("$slave/laser_localise0.rtc", localisation.path("laser_localise0.rtc")), find("--name", "*local*", "--type", "component"))
        assertEquals(listOf("$slave/laser_localise0.rtc", localisation.path("laser_localise0.rtc")), find("--port", "pose"))
        assertEquals(emptyList<String>(), find("--state", "error"))
        assertEquals(listOf("$slave/gyro0.rtc", localisation.path("gyro0.rtc")), find("--state", "active", "--name", "gyro?.rtc"))
    }

    @Test
    fun `--json gives paths and kinds`() {
        val json = runRtcoord("--json", "find", host, "--type", "context").ok()
        assertEquals("[\n  {\n    \"path\": \"$host\",\n    \"kind\": \"context\"\n  }\n]\n", json)
    }

    @Test
    fun `an unknown state is a usage error`() {
        runRtcoord("find", host, "--state", "sleepy").usageError()
    }
}
