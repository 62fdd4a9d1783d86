package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/**
 * `rtcoord test --explore`: a line per run with its seed and index, each distinct failure once with its replay command,
 * JUnit XML; `--replay` with its agreement; a test with nothing to check refused.
 */
class TestExploreCommandTest {
    private val system = Path.of("../examples/localisation.xml").toAbsolutePath().normalize()

    private fun write(directory: Path, name: String, text: String): Path =
        directory.resolve(name).also { Files.writeString(it, text.trimIndent() + "\n") }

    @Test
    fun `explore prints each run and the distinct failure with its replay command, writes JUnit XML, and --replay reruns it`(
        @TempDir directory: Path
    ) {
        write(directory, "boom.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) {\n    error(\"boom\")\n}")
        val test =
            write(
                directory,
                "boom.test.kts",
                """
            system("$system")
            coordinator("boom.coord.kts")
            explore {
                components("laser0")
                faults { fail() }
                window(0.seconds, 300.milliseconds)
            }
            expect { component("gyro0").state() == ACTIVE }
            """,
            )
        val junit = directory.resolve("junit")
        val explored =
            runRtcoord(
                "test",
                "--explore",
                "--runs",
                "2",
                "--seed",
                "3",
                "--max-faults",
                "1",
                "--parallel",
                "1",
                "--no-write",
                "--junit",
                junit.toString(),
                test.toString(),
            )
        assertEquals(1, explored.statusCode, explored.stdout + explored.stderr)
        val out = explored.stdout
        assertTrue(
            out.lines().first() ==
                "exploring $test: seed 3, 2 runs, up to 1 faults a run, 1 at a time, 10x the robot's clock",
            out,
        )
        assertTrue(
            Regex(
                    """run 3:0 FAIL \S+boom\.coord\.kts:2: rule 'laser0\.rtc enters ERROR' failed: IllegalStateException: boom › boom: \d+\.\d{3} s fail laser0"""
                )
                .containsMatchIn(out),
            out,
        )
        assertTrue(out.contains("run 3:1 FAIL "), out)
        assertEquals(1, out.lines().count { it.startsWith("FAIL ") }, out)
        assertTrue(out.contains("  replay: rtcoord test --explore --replay 3:0 --max-faults 1 $test"), out)
        assertTrue(
            Regex(
                    """2 runs in \d+\.\d s: 2 failed \(1 distinct\), 0 skipped; \d+\.\d schedules/min, \d+\.\dx the robot's clock"""
                )
                .containsMatchIn(out),
            out,
        )
        assertTrue(Files.readString(junit.resolve("TEST-boom.explore.xml")).contains("tests=\"1\" failures=\"1\""))

        val replayed =
            runRtcoord(
                "test",
                "--explore",
                "--replay",
                "3:0",
                "--max-faults",
                "1",
                "--reruns",
                "2",
                "--parallel",
                "1",
                test.toString(),
            )
        assertEquals(1, replayed.statusCode, replayed.stdout + replayed.stderr)
        assertTrue(replayed.stdout.contains("rerun agreement: 2 of 2 (100%) had that verdict"), replayed.stdout)
    }

    @Test
    fun `a test with nothing to check is refused in one line, and so is a malformed replay key`(
        @TempDir directory: Path
    ) {
        write(directory, "quiet.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { log(\"laser\") }")
        val test =
            write(
                directory,
                "quiet.test.kts",
                "system(\"$system\")\ncoordinator(\"quiet.coord.kts\")\nat(1.seconds) { fail(\"laser0\") }",
            )
        val refused = runRtcoord("test", "--explore", test.toString())
        assertEquals(1, refused.statusCode, refused.stdout + refused.stderr)
        assertTrue(
            refused.stderr
                .trim()
                .endsWith(
                    "$test: nothing to check: the test has no invariant (always, never) and no expectation, so no schedule could fail it"
                ),
            refused.stderr,
        )
        val key = runRtcoord("test", "--explore", "--replay", "3-0", test.toString())
        assertEquals(1, key.statusCode)
        assertEquals("rtcoord: --replay 3-0: give SEED:INDEX, as a run's line shows it (e.g. 42:17)", key.stderr.trim())
        val speed = runRtcoord("test", "--explore", "--speed", "0", test.toString())
        // A usage error, as Clikt reports one.
        assertEquals(2, speed.statusCode)
        assertTrue(speed.stderr.trim().endsWith("invalid value for --speed: must be positive"), speed.stderr)
    }
}
