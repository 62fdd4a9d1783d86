package org.rtcoord.cli

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
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
    fun `rtcoord sim on a file that is no profile fails in one line naming it`(@TempDir directory: Path) {
        val file = directory.resolve("broken.xml").also { Files.writeString(it, "<nothing") }
        assertTrue(runRtcoord("sim", file.toString()).failure().contains("broken.xml"))
    }
}
