package org.rtcoord.sim.explore

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.test.CoordinatorTestRunner
import org.rtcoord.sim.test.TestReport

/**
 * `rtcoord test --explore` end to end on the examples' system: schedules drawn from a seed find a coordinator's fault,
 * shrink it to one fault at a round time, write it as a test that fails as written, and replay it by its seed; what
 * cannot be explored is refused, what cannot be applied is skipped.
 */
class ExploreTest {
    private val system = Paths.get("../examples/localisation.xml").toAbsolutePath().normalize()

    private fun write(directory: Path, name: String, text: String): Path =
        directory.resolve(name).also { Files.writeString(it, text.trimIndent() + "\n") }

    /** A coordinator whose handler fails when laser0 goes to ERROR, and a test whose expectation cannot see it. */
    private fun boom(directory: Path, explore: String): Path {
        write(directory, "boom.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) {\n    error(\"boom\")\n}")
        return write(
            directory,
            "boom.test.kts",
            """
            system("$system")
            coordinator("boom.coord.kts")
            explore {
            $explore
            }
            scenario("the gyro runs") {
                expect { component("gyro0").state() == ACTIVE }
            }
            """,
        )
    }

    @Test
    fun `a failure is found, shrunk to its smallest schedule, written as a test that fails, and replayed by its seed`(
        @TempDir directory: Path
    ) {
        val test =
            boom(
                directory,
                "components(\"laser0\", \"gyro0\"); faults { fail(); breakDown() }; window(0.seconds, 1.seconds)",
            )
        val explorer = FaultExplorer(ScriptHost())
        val lines = mutableListOf<ExploreProgress>()
        val report = runBlocking {
            explorer.explore(test, ExploreOptions(seed = 7, runs = 4, maxFaults = 3, shrinkRuns = 12), lines::add)
        }

        assertEquals(4, report.runs)
        assertEquals((0..3).map { "7:$it" }, lines.map { it.key }.sorted())
        val found = report.failures.single()
        assertEquals("${directory.resolve("boom.coord.kts")}:2", found.failure.at)
        assertEquals(report.failed, found.occurrences)
        // Fewer faults, one component, earlier and rounder: the laser's one fault at the start.
        assertEquals(1, found.faults, found.smallest)
        assertTrue(Regex("""0\.000 s (fail|breakDown) laser0""").matches(found.smallest), found.smallest)
        val written = requireNotNull(found.test) { "no test written" }
        assertEquals("boom.found-${found.firstRun.replace(':', '-')}.test.kts", written.fileName.toString())
        val text = Files.readString(written)
        assertTrue(text.contains("meanwhile {\n        at(0.seconds) {"), text)
        assertEquals(true, found.failsAsWritten)

        val rerun = runBlocking { CoordinatorTestRunner().let { it.runAll(it.files(listOf(written))) } }.single()
        assertEquals(
            "${directory.resolve("boom.coord.kts")}:2",
            rerun.failures.first().at,
            TestReport.failures(rerun).joinToString("\n"),
        )

        val (seed, index) = found.firstRun.split(':').map(String::toLong)
        val replayed = runBlocking { explorer.replay(test, seed, index, 3, reruns = 2) }
        assertEquals(found.drawn, replayed.schedule)
        assertTrue(replayed.failed && replayed.agreeing == 2, replayed.verdicts.toString())
    }

    @Test
    fun `an exploration stopped early reports what it found so far, unshrunk`(@TempDir directory: Path) {
        val test = boom(directory, "components(\"laser0\"); faults { fail() }; window(0.seconds, 200.milliseconds)")
        val explorer = FaultExplorer(ScriptHost())
        val report = runBlocking {
            explorer.explore(test, ExploreOptions(seed = 2, runs = 50, maxFaults = 1)) { explorer.stop() }
        }
        assertTrue(report.interrupted)
        assertTrue(report.runs in 1..2, "runs: ${report.runs}")
        val found = report.failures.single()
        assertEquals(found.drawn, found.smallest)
        assertEquals(null, found.test)
    }

    @Test
    fun `a fault that cannot be applied skips its run, counted with why`(@TempDir directory: Path) {
        val test = boom(directory, "components(\"ghost0\"); faults { exit() }; window(0.seconds, 200.milliseconds)")
        val report = runBlocking {
            FaultExplorer(ScriptHost()).explore(test, ExploreOptions(seed = 1, runs = 2, maxFaults = 1))
        }
        assertEquals(2, report.skipped)
        assertEquals(0, report.failed)
        assertEquals(mapOf("no component ghost0 in the simulated system" to 2), report.skipReasons)
    }

    @Test
    fun `a test with nothing to check, or one failing without faults, is refused`(@TempDir directory: Path) {
        write(directory, "quiet.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { log(\"laser\") }")
        val nothing =
            write(
                directory,
                "nothing.test.kts",
                "system(\"$system\")\ncoordinator(\"quiet.coord.kts\")\nat(1.seconds) { fail(\"laser0\") }",
            )
        val refused =
            assertThrows<ExploreRefused> {
                runBlocking { FaultExplorer(ScriptHost()).explore(nothing, ExploreOptions(seed = 1, runs = 1)) }
            }
        assertEquals(
            listOf(
                "$nothing: nothing to check: the test has no invariant (always, never) and no expectation, so no schedule could fail it"
            ),
            refused.lines,
        )

        val failing =
            write(
                directory,
                "failing.test.kts",
                "system(\"$system\")\ncoordinator(\"quiet.coord.kts\")\nexpect(within = 200.milliseconds) { component(\"laser0\").state() == ERROR }",
            )
        val baseline =
            assertThrows<ExploreRefused> {
                runBlocking { FaultExplorer(ScriptHost()).explore(failing, ExploreOptions(seed = 1, runs = 1)) }
            }
        assertEquals("failing fails without any fault injected; fix it (or the test) first:", baseline.lines.first())
        assertFalse(baseline.lines.drop(1).isEmpty())
    }
}
