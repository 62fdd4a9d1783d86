package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.attribute.PosixFilePermissions
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.api.io.TempDir

/** `graph`: DOT compared with a golden file, and `--svg` through whatever `dot` the PATH offers. */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class GraphCommandTest {
    private val localisation = Localisation()

    @AfterAll fun stop() = localisation.close()

    private fun golden(name: String): String = GraphCommandTest::class.java.getResource("/golden/$name")!!.readText()

    @Test
    fun `the localisation system as DOT`() {
        assertEquals(golden("localisation.dot"), runRtcoord("graph", localisation.host).ok())
    }

    @Test
    fun `one component with its neighbours outside, dashed`() {
        val dot = runRtcoord("graph", localisation.path("laser0.rtc")).ok()
        assertEquals(golden("laser0.dot"), dot.replace(localisation.host, "/HOST"))
    }

    @Test
    fun `--svg runs dot from the PATH`(@TempDir directory: Path) {
        // A stand-in for Graphviz that records its arguments and its input, so the test needs no Graphviz.
        val dot = directory.resolve("dot")
        Files.writeString(dot, "#!/bin/sh\necho \"$@\" > \"${directory.resolve("arguments")}\"\ncat > \"$3\"\n")
        Files.setPosixFilePermissions(dot, PosixFilePermissions.fromString("rwxr-xr-x"))
        val svg = directory.resolve("system.svg")
        assertEquals(
            "",
            runRtcoord(
                    "graph",
                    localisation.host,
                    "--svg",
                    svg.toString(),
                    environment = mapOf("PATH" to directory.toString()),
                )
                .ok(),
        )
        assertEquals("-Tsvg -o $svg\n", Files.readString(directory.resolve("arguments")))
        assertEquals(golden("localisation.dot"), Files.readString(svg))
    }

    @Test
    fun `--svg without dot on the PATH is a clear error`(@TempDir directory: Path) {
        val line =
            runRtcoord(
                    "graph",
                    localisation.host,
                    "--svg",
                    directory.resolve("x.svg").toString(),
                    environment = mapOf("PATH" to directory.toString()),
                )
                .failure()
        assertEquals(
            "rtcoord: dot: not found on PATH: install Graphviz for --svg, or leave --svg out to print DOT",
            line,
        )
    }

    @Test
    fun `a failing dot is reported with what it said`(@TempDir directory: Path) {
        val dot = directory.resolve("dot")
        Files.writeString(dot, "#!/bin/sh\necho 'Error: syntax error in line 1' >&2\nexit 1\n")
        Files.setPosixFilePermissions(dot, PosixFilePermissions.fromString("rwxr-xr-x"))
        val line =
            runRtcoord(
                    "graph",
                    localisation.host,
                    "--svg",
                    directory.resolve("x.svg").toString(),
                    environment = mapOf("PATH" to directory.toString()),
                )
                .failure()
        assertEquals("rtcoord: dot: Error: syntax error in line 1", line)
    }
}
