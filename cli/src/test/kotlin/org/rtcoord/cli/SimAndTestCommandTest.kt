package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.runtime.RuntimeProcess

/**
 * `rtcoord test DIR` passes and writes JUnit XML; a run whose tests fail in every way reports each and exits 1;
 * `rtcoord sim` refuses a profile it cannot simulate in one line.
 */
class SimAndTestCommandTest {
    @Test
    fun `rtcoord test DIR passes, prints a line per scenario and a summary with the wall time, and writes JUnit XML`(
        @TempDir directory: Path
    ) {
        // Two of the examples' test files with what they name; examples' ExampleTestFilesTest runs them all.
        val examples = Path.of("../examples")
        val tests = Files.createDirectories(directory.resolve("tests"))
        for (name in
            listOf(
                "frozen-laser.test.kts",
                "frozen-laser.coord.kts",
                "modes.test.kts",
                "modes.coord.kts",
                "localisation.xml",
            )) Files.copy(examples.resolve(name), tests.resolve(name))
        val junit = directory.resolve("junit")
        // On the robot's clock, as ExampleTestFilesTest runs them: faster, the laser's 500 ms silence rule fires on a
        // stall of a fraction of that on a loaded machine (at ten times, 50 ms), and "no switch" fails.
        val result = runRtcoord("test", "--junit", junit.toString(), tests.toString())
        assertEquals(0, result.statusCode, result.stdout + result.stderr)
        val scenarios = result.stdout.lines().filter { it.startsWith("PASS ") }
        assertEquals(6, scenarios.size, result.stdout)
        assertTrue(scenarios.any { it.startsWith("PASS ${tests.resolve("modes.test.kts")} › ") }, result.stdout)
        val summary = Regex("""6 scenarios in 2 files, 6 passed, 0 failed \(wall time \d+\.\d s\)""")
        assertTrue(summary.matches(result.stdout.trimEnd().lines().last()), result.stdout)
        for (name in listOf("frozen-laser", "modes")) assertTrue(
            Files.readString(junit.resolve("TEST-$name.xml")).contains("failures=\"0\""),
            name,
        )
    }

    @Test
    fun `a handler that fails, a rule on what the system lacks and two files of one name each fail and report, the others pass`(
        @TempDir directory: Path
    ) {
        val system = Path.of("../examples/localisation.xml").toAbsolutePath().normalize()
        fun write(name: String, text: String) =
            directory.resolve(name).also {
                Files.createDirectories(it.parent)
                Files.writeString(it, text.trimIndent() + "\n")
            }
        write("a/boom.coord.kts", """on(component("laser0.rtc")).state(ERROR) { error("boom") }""")
        write("b/lidar.coord.kts", """on(component("lidar0.rtc")).state(ERROR) { log("lidar") }""")
        val a =
            write(
                "a/transient.test.kts",
                "system(\"$system\")\ncoordinator(\"boom.coord.kts\")\nat(1.seconds) { fail(\"laser0\") }\nexpect(within = 5.seconds) { component(\"laser0\").state() == ERROR }",
            )
        val b =
            write(
                "b/transient.test.kts",
                "system(\"$system\")\ncoordinator(\"lidar.coord.kts\")\nexpect { component(\"laser0\").state() == ACTIVE }",
            )
        val c =
            write(
                "c/fine.test.kts",
                "system(\"$system\")\ncoordinator(\"../a/boom.coord.kts\")\nnever { component(\"laser0\").state() == ERROR }\nexpect { component(\"gyro0\").state() == ACTIVE }",
            )

        val result =
            runRtcoord(
                "test",
                "--junit",
                directory.resolve("junit").toString(),
                a.toString(),
                b.toString(),
                c.toString(),
            )
        assertEquals(1, result.statusCode, result.stdout + result.stderr)
        val out = result.stdout
        assertTrue(out.contains("FAIL $a ("), out)
        assertTrue(
            out.contains(
                "  ${directory.resolve("a/boom.coord.kts")}:1: rule 'laser0.rtc enters ERROR' failed: IllegalStateException: boom"
            ),
            out,
        )
        assertTrue(out.contains("FAIL $b ("), out)
        assertTrue(out.contains("  ${directory.resolve("b/lidar.coord.kts")}:1:14: lidar0.rtc: no such component"), out)
        assertTrue(Regex("""\s+\d+\.\d{3} s {2}fault {2}fail laser0""").containsMatchIn(out), out)
        assertTrue(out.contains("PASS $c ("), out)
        assertTrue(
            out.trimEnd().lines().last().startsWith("3 scenarios in 3 files, 1 passed, 2 failed (wall time "),
            out,
        )
        val reports =
            Files.list(directory.resolve("junit")).use { files ->
                files.map { it.fileName.toString() }.sorted().toList()
            }
        assertEquals(listOf("TEST-a.transient.xml", "TEST-b.transient.xml", "TEST-fine.xml"), reports)
    }

    @Test
    fun `rtcoord sim --help lists the commands it takes on stdin one a line`() {
        val help = runRtcoord("sim", "--help")
        assertEquals(0, help.statusCode, help.stderr)
        val lines = help.stdout.lines().map { it.trim() }
        for (command in
            listOf(
                "activate NAME",
                "fail NAME",
                "break NAME",
                "hang NAME",
                "freeze NAME",
                "repair NAME",
                "exit NAME",
                "kill-manager",
                "restart-naming",
                "help",
            )) {
            assertTrue(lines.any { it.startsWith("$command ") }, "a line of its own for $command:\n${help.stdout}")
        }
    }

    @Test
    fun `rtcoord sim --compare finds no difference from the system a profile was saved from, and names each one it finds`(
        @TempDir directory: Path
    ) {
        Localisation().use { live ->
            val saved = directory.resolve("localisation.xml")
            runRtcoord("profile", "save", "/${live.naming.address}", "-o", saved.toString()).ok()
            val same = runRtcoord("sim", "--compare", "/${live.naming.address}", saved.toString())
            assertEquals(0, same.statusCode, same.stderr)
            assertEquals(
                "no difference from /${live.naming.address}: 4 components, 2 connections, 2 managers compared\n",
                same.stdout,
            )

            val slower = directory.resolve("slower.xml")
            Files.writeString(slower, Files.readString(saved).replaceFirst("rts:rate=\"100.0\"", "rts:rate=\"25.0\""))
            val differs = runRtcoord("sim", "--compare", "/${live.naming.address}", slower.toString())
            assertEquals(1, differs.statusCode)
            assertEquals(
                "/${RuntimeProcess.hostContext}/laser0.rtc: execution context 0: rate: 100.0 live, 25.0 simulated\n",
                differs.stdout,
            )
            assertTrue(
                differs.stderr
                    .trimEnd()
                    .endsWith(
                        "rtcoord: $slower: 1 difference from /${live.naming.address} (4 components, 2 connections, 2 managers compared)"
                    ),
                differs.stderr,
            )
        }
    }

    @Test
    fun `rtcoord sim on a file that is no profile fails in one line naming it`(@TempDir directory: Path) {
        val file = directory.resolve("broken.xml").also { Files.writeString(it, "<nothing") }
        assertTrue(runRtcoord("sim", file.toString()).failure().contains("broken.xml"))
    }
}
