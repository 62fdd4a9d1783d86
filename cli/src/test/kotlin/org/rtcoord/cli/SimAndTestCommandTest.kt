package org.rtcoord.cli

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.runtime.RuntimeProcess
import java.nio.file.Files
import java.nio.file.Path

/** `rtcoord test examples/` passes and writes JUnit XML; `rtcoord sim` refuses a profile it cannot simulate in one line. */
class SimAndTestCommandTest {
    @Test
    fun `rtcoord test examples passes, prints a summary and writes JUnit XML`(@TempDir junit: Path) {
        val result = runRtcoord("test", "--junit", junit.toString(), "../examples/")
        assertEquals(0, result.statusCode, result.stdout + result.stderr)
        assertTrue(result.stdout.lines().any { it.startsWith("PASS ") && it.contains("localisation.test.kts") }, result.stdout)
        val tests = Files.list(Path.of("../examples")).use { files -> files.filter { it.toString().endsWith(".test.kts") }.count() }
        assertTrue(tests >= 3, "examples/*.test.kts: $tests")
        assertTrue(result.stdout.trimEnd().endsWith("$tests tests, $tests passed, 0 failed"), result.stdout)
        for (name in listOf("localisation", "frozen-laser", "modes")) assertTrue(Files.readString(junit.resolve("TEST-$name.xml")).contains("failures=\"0\""), name)
    }

    @Test
    fun `rtcoord sim --compare finds no difference from the system a profile was saved from, and names each one it finds`(@TempDir directory: Path) {
        Localisation().use { live ->
            val saved = directory.resolve("localisation.xml")
            runRtcoord("profile", "save", "/${live.naming.address}", "-o", saved.toString()).ok()
            val same = runRtcoord("sim", "--compare", "/${live.naming.address}", saved.toString())
            assertEquals(0, same.statusCode, same.stderr)
            assertEquals("no difference from /${live.naming.address}: 4 components, 2 connections, 2 managers compared\n", same.stdout)

            val slower = directory.resolve("slower.xml")
            Files.writeString(slower, Files.readString(saved).replaceFirst("rts:rate=\"100.0\"", "rts:rate=\"25.0\""))
            val differs = runRtcoord("sim", "--compare", "/${live.naming.address}", slower.toString())
            assertEquals(1, differs.statusCode)
            assertEquals("/${RuntimeProcess.hostContext}/laser0.rtc: execution context 0: rate: 100.0 live, 25.0 simulated\n", differs.stdout)
            assertTrue(differs.stderr.trimEnd().endsWith("rtcoord: $slower: 1 difference from /${live.naming.address} (4 components, 2 connections, 2 managers compared)"), differs.stderr)
        }
    }

    @Test
    fun `rtcoord sim on a file that is no profile fails in one line naming it`(@TempDir directory: Path) {
        val file = directory.resolve("broken.xml").also { Files.writeString(it, "<nothing") }
        assertTrue(runRtcoord("sim", file.toString()).failure().contains("broken.xml"))
    }
}
