package org.rtcoord.cli

import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.ValueSource

/** The root command's options, usage errors, help and the error format every command shares. */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class GlobalOptionsTest {
    private val localisation = Localisation()
    private val address = localisation.naming.address

    @AfterAll fun stop() = localisation.close()

    @Test
    fun `--version prints the project version`() {
        assertTrue(Regex("""rtcoord \d+\.\d+\.\d+(-SNAPSHOT)?\n""").matches(runRtcoord("--version").ok()))
    }

    @ParameterizedTest
    @ValueSource(
        strings =
            ["ls", "cat", "find", "act", "deact", "reset", "exit", "con", "dis", "conf", "mgr", "del", "watch", "graph"]
    )
    fun `every command has help with examples`(command: String) {
        val help = runRtcoord(command, "--help").ok()
        assertTrue(help.startsWith("Usage: rtcoord $command"), help)
        assertTrue("\nExamples:\n  rtcoord " in help, help)
    }

    @Test
    fun `usage errors exit 2 with Clikt's message`() {
        assertTrue("Commands:" in runRtcoord().usageError())
        assertTrue("no such subcommand" in runRtcoord("lst").usageError())
        assertTrue("no such option" in runRtcoord("ls", "--long").usageError())
        assertTrue("'fast' is not a positive duration" in runRtcoord("--timeout", "fast", "ls", "/").usageError())
        assertTrue("bad path" in runRtcoord("-n", "host:port:x", "ls").usageError())
        assertTrue(
            "RTCOORD_NAMESERVERS" in
                runRtcoord("ls", environment = mapOf("RTCOORD_NAMESERVERS" to "a:b:c")).usageError()
        )
        assertTrue(
            "--listen: 203.0.113.7 is not an address of this host" in
                runRtcoord("--listen", "203.0.113.7", "ls", "/").usageError()
        )
    }

    @Test
    fun `-n wins over RTCOORD_NAMESERVERS, which wins over RTCTREE_NAMESERVERS`() {
        val dead = deadNameServer()
        val both = mapOf("RTCOORD_NAMESERVERS" to address, "RTCTREE_NAMESERVERS" to dead)
        assertEquals("$address/\n", runRtcoord("ls", "/", environment = both).ok())
        assertEquals(
            "$address/\n",
            runRtcoord("-n", address, "ls", "/", environment = mapOf("RTCOORD_NAMESERVERS" to dead)).ok(),
        )
        val listed = runRtcoord("ls", "/", environment = mapOf("RTCTREE_NAMESERVERS" to "$address;$dead"))
        assertEquals("$address/\n", listed.stdout)
        assertTrue(listed.stderr.startsWith("rtcoord: /$dead: unreachable"), listed.stderr)
        assertEquals(1, listed.statusCode)
    }

    @Test
    fun `--timeout bounds every call, so a hung component is one zombie line`() {
        val gyro = localisation.system.component("gyro0")
        gyro.hang()
        try {
            val started = System.nanoTime()
            val listed = runRtcoord("--timeout", "500ms", "ls", "-l", localisation.host).ok()
            assertTrue("-       -    -    -    -    *gyro0.rtc\n" in listed, listed)
            assertTrue(
                System.nanoTime() - started < 3_000_000_000L,
                "took ${(System.nanoTime() - started) / 1_000_000} ms",
            )
        } finally {
            gyro.release()
        }
    }

    @Test
    fun `-q leaves out confirmations`() {
        val laser = localisation.path("laser0.rtc:laser")
        val localiser = localisation.path("laser_localise0.rtc:laser")
        assertEquals("", runRtcoord("-q", "con", laser, localiser, "--allow-duplicate", "--id", "quiet").ok())
        runRtcoord("dis", laser, "--id", "quiet").ok()
    }
}
