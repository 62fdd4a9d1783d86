package org.rtcoord.cli

import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.rtcoord.fixtures.runPeer
import org.rtcoord.runtime.RuntimeProcess

/** `ls` against the localisation system, checked against rtshell's rtls where both can list it. */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class LsCommandTest {
    private val localisation = Localisation()
    private val host = localisation.host
    private val address = localisation.naming.address

    @AfterAll fun stop() = localisation.close()

    @Test
    fun `the short form lists names, directories with a slash`() {
        val listed = runRtcoord("ls", host).ok()
        assertEquals("manager.mgr/\nlaser0.rtc\ngyro0.rtc\nodometry0.rtc\nlaser_localise0.rtc\n", listed)
    }

    @Test
    fun `the long form is rtls -l's, column for column`() {
        val ours = runRtcoord("ls", "-l", host).ok()
        assertEquals(
            """
            -       -    -    -    -    manager.mgr
            Active  1/1  0/0  1/1  0/0  laser0.rtc
            Active  1/0  0/0  1/0  0/0  gyro0.rtc
            Active  1/1  0/0  1/1  0/0  odometry0.rtc
            Active  3/2  2/2  1/0  0/0  laser_localise0.rtc

            """
                .trimIndent(),
            ours,
        )
        assertEquals(runPeer("rtls", "-l", host).ok().output, ours)
    }

    @Test
    fun `-l -R is rtls -l -R, headers and all`() {
        val ours = runRtcoord("ls", "-l", "-R", "/$address/").ok()
        assertTrue(
            ours.startsWith(".:\n-  -  -  -  -  ${RuntimeProcess.hostContext}\n\n./${RuntimeProcess.hostContext}:\n"),
            ours,
        )
        assertEquals(withoutSlavesComponentsUnderMaster(runPeer("rtls", "-l", "-R", "/$address/").ok().output), ours)
    }

    /**
     * [listing] with the master's section holding only its slaves: a master's `get_components` includes its slaves'
     * components, which rtls shows twice (below the master and below the slave), rtcoord once.
     */
    private fun withoutSlavesComponentsUnderMaster(listing: String): String {
        val header = "./${RuntimeProcess.hostContext}/manager.mgr:\n"
        val start = listing.indexOf(header) + header.length
        val end = listing.indexOf("\n\n", start)
        // Without the components' wider columns, the managers' dashes take rtls's narrowest padding.
        val section =
            listing
                .substring(start, end)
                .lines()
                .filterNot { it.endsWith(".rtc") }
                .joinToString("\n") { it.replace(Regex(" {2,}"), "  ") }
        return listing.substring(0, start) + section + listing.substring(end)
    }

    @Test
    fun `a name server without a trailing slash is listed, where rtls reads a port`() {
        assertEquals("${RuntimeProcess.hostContext}/\n", runRtcoord("ls", "/$address").ok())
        assertEquals(1, runPeer("rtls", "/$address").exitCode)
    }

    @Test
    fun `with no path the root context of the name server from -n or the environment is listed, as rtls lists it`() {
        val root = "${RuntimeProcess.hostContext}/\n"
        assertEquals(root, runRtcoord("-n", address, "ls").ok())
        assertEquals(root, runRtcoord("ls", environment = mapOf("RTCOORD_NAMESERVERS" to address)).ok())
        assertEquals(root, runRtcoord("ls", environment = mapOf("RTCTREE_NAMESERVERS" to " $address ;")).ok())
        // '/' lists the name servers themselves.
        assertEquals("$address/\n", runRtcoord("-n", address, "ls", "/").ok())
    }

    @Test
    fun `-n NS ls -l is rtls -l of the name server's root, and with -R everything it knows`() {
        val ours = runRtcoord("-n", address, "ls", "-l").ok()
        assertEquals("-  -  -  -  -  ${RuntimeProcess.hostContext}\n", ours)
        assertEquals(runPeer("rtls", "-l", "/$address/").ok().output, ours)
        assertEquals(runRtcoord("ls", "-l", "-R", "/$address/").ok(), runRtcoord("-n", address, "ls", "-l", "-R").ok())
    }

    @Test
    fun `several name servers are listed each under its own header, an unreachable one an error line`() {
        val dead = deadNameServer()
        val listed = runRtcoord("-n", address, "-n", dead, "ls")
        assertEquals("/$address/:\n${RuntimeProcess.hostContext}/\n", listed.stdout)
        assertTrue(
            listed.stderr.matches(Regex("rtcoord: /${Regex.escape(dead)}: unreachable \\(.+\\)\n")),
            listed.stderr,
        )
        assertEquals(1, listed.statusCode)
    }

    @Test
    fun `with no name server configured, ls says so and how to give one, with status 1`() {
        val expected =
            "rtcoord: no name server configured: give -n HOST[:PORT], or set RTCOORD_NAMESERVERS (or rtshell's RTCTREE_NAMESERVERS), " +
                "e.g. RTCOORD_NAMESERVERS=localhost"
        assertEquals(expected, runRtcoord("ls").failure())
        assertEquals(expected.replace("rtcoord: ", "rtcoord: /: "), runRtcoord("ls", "/").failure())
        assertEquals(expected.replace("rtcoord: ", "rtcoord: /: "), runRtcoord("ls", "-l", "-R", "/").failure())
    }

    @Test
    fun `a dead name server among live ones is an error line and status 1, the live ones still listed`() {
        val dead = deadNameServer()
        val listed = runRtcoord("-n", address, "-n", dead, "ls", "-l", "/")
        assertEquals("-  -  -  -  -  $address\n", listed.stdout)
        assertTrue(
            listed.stderr.matches(Regex("rtcoord: /${Regex.escape(dead)}: unreachable \\(.+\\)\n")),
            listed.stderr,
        )
        assertEquals(1, listed.statusCode)
        // rtls fails on it too, with an error.
        val theirs = runPeer("rtls", "/$dead/")
        assertEquals(1, theirs.exitCode)
        assertTrue(theirs.errors.startsWith("rtls: "), theirs.errors)
    }

    @Test
    fun `a manager's port given as a name server is an error line saying so, in the long form too`() {
        val managerPort = localisation.system.master!!.runtime.orb.let { "${it.host}:${it.port}" }
        val expected = "rtcoord: /$managerPort: is a manager (IDL:RTM/Manager:1.0), not a name server\n"
        for (arguments in listOf(listOf("ls", "/"), listOf("ls", "-l", "/"), listOf("ls", "-l"))) {
            val listed = runRtcoord("-n", managerPort, *arguments.toTypedArray())
            assertEquals("" to expected, listed.stdout to listed.stderr, arguments.joinToString(" "))
            assertEquals(1, listed.statusCode)
        }
    }

    @Test
    fun `each dead name server has its own line, under -R and --json too`() {
        val dead = listOf(deadNameServer(), deadNameServer())
        val recursive = runRtcoord("-n", dead[0], "-n", address, "-n", dead[1], "ls", "-R", "/")
        assertEquals(1, recursive.statusCode)
        assertTrue(recursive.stdout.startsWith(".:\n$address/\n"), recursive.stdout)
        assertEquals(
            dead.map { "rtcoord: /$it" },
            recursive.stderr.lines().filter { it.isNotEmpty() }.map { it.substringBefore(": unreachable") },
        )
        val json = runRtcoord("-n", dead[0], "--json", "ls", "/")
        assertEquals(1, json.statusCode)
        assertEquals("[]\n", json.stdout)
        assertTrue(json.stderr.startsWith("rtcoord: /${dead[0]}: unreachable"), json.stderr)
    }

    @Test
    fun `a component path lists that component`() {
        assertEquals(
            "Active  1/0  0/0  1/0  0/0  gyro0.rtc\n",
            runRtcoord("ls", "-l", localisation.path("gyro0.rtc")).ok(),
        )
        assertEquals("gyro0.rtc\n", runRtcoord("ls", localisation.path("gyro0.rtc")).ok())
    }

    @Test
    fun `several paths are listed under their own headers`() {
        val listed =
            runRtcoord("ls", localisation.path("manager.mgr"), localisation.path("manager.mgr/manager_slave")).ok()
        assertEquals(
            "${localisation.path("manager.mgr")}:\nmanager_slave/\n\n" +
                "${localisation.path("manager.mgr/manager_slave")}:\nlaser0.rtc\ngyro0.rtc\nodometry0.rtc\nlaser_localise0.rtc\n",
            listed,
        )
    }

    @Test
    fun `--json gives every entry with its state and port counts`() {
        val json = runRtcoord("--json", "ls", localisation.path("gyro0.rtc")).ok()
        val expected =
            """
            [
              {
                "path": "${localisation.path("gyro0.rtc")}",
                "name": "gyro0.rtc",
                "kind": "component",
                "state": "ACTIVE",
                "ports": {
                  "all": {
                    "total": 1,
                    "connected": 0
                  },
                  "in": {
                    "total": 0,
                    "connected": 0
                  },
                  "out": {
                    "total": 1,
                    "connected": 0
                  },
                  "service": {
                    "total": 0,
                    "connected": 0
                  }
                }
              }
            ]
            
        """
                .trimIndent()
        assertEquals(expected, json)
    }

    @Test
    fun `relative paths start from RTCOORD_CWD or rtshell's RTCSH_CWD`() {
        assertEquals("gyro0.rtc\n", runRtcoord("ls", "gyro0.rtc", environment = mapOf("RTCOORD_CWD" to host)).ok())
        assertEquals(
            "gyro0.rtc\n",
            runRtcoord("ls", "../${RuntimeProcess.hostContext}/gyro0.rtc", environment = mapOf("RTCSH_CWD" to "$host/"))
                .ok(),
        )
        // Without a path, the working directory is what ls lists, as rtls does.
        assertEquals(
            runRtcoord("ls", host).ok(),
            runRtcoord("-n", address, "ls", environment = mapOf("RTCOORD_CWD" to host)).ok(),
        )
    }

    @Test
    fun `relative paths start at the first name server given, else the error says how to give a start`() {
        val hostContext = RuntimeProcess.hostContext
        assertEquals("gyro0.rtc\n", runRtcoord("-n", address, "ls", "$hostContext/gyro0.rtc").ok())
        assertEquals(
            "gyro0.rtc\n",
            runRtcoord("-n", address, "-n", deadNameServer(), "ls", "$hostContext/gyro0.rtc").ok(),
        )
        assertEquals(
            "gyro0.rtc\n",
            runRtcoord("ls", "$hostContext/gyro0.rtc", environment = mapOf("RTCOORD_NAMESERVERS" to address)).ok(),
        )
        assertEquals(
            "rtcoord: $hostContext/gyro0.rtc: a relative path needs a start: give -n HOST[:PORT] (relative paths start at the first name server) or set RTCOORD_CWD",
            runRtcoord("ls", "$hostContext/gyro0.rtc").failure(),
        )
    }
}
