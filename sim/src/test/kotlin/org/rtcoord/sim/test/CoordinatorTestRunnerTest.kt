package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/**
 * `*.test.kts` files run against systems simulated from a profile: the paper's scenario, scenarios, and what failures
 * say.
 */
class CoordinatorTestRunnerTest {
    private fun run(vararg files: Path): List<TestResult> = runBlocking {
        CoordinatorTestRunner().let { it.runAll(it.files(files.toList())) }
    }

    @Test
    fun `each scenario runs on a system of its own after the steps at the top, and is a test case of its own`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val test =
            folder.test(
                "two.test.kts",
                "${folder.examples}/localisation.coord.kts",
                """
            expect(within = 2.seconds) { component("laser_localise0").state() == ACTIVE }
            scenario("the laser breaks") {
                at(1.seconds) { breakDown("laser0") }
                expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
            }
            scenario("nothing happens") {
                expect { !component("odo_localise0").exists() && component("laser0").state() == ACTIVE }
            }
            """,
            )
        val results = run(test)
        assertEquals(listOf("the laser breaks", "nothing happens"), results.map { it.scenario })
        results.forEach { assertTrue(it.passed, TestReport.failures(it).joinToString("\n")) }

        val xml = Files.readString(JUnitXml.write(results, directory.resolve("junit")).single())
        assertTrue(xml.contains("tests=\"2\" failures=\"0\""), xml)
        assertTrue(xml.contains("<testcase classname=\"two\" name=\"the laser breaks\""), xml)
        assertTrue(xml.contains("<testcase classname=\"two\" name=\"nothing happens\""), xml)
    }

    @Test
    fun `a scenario at ten times the robot's clock holds as on it, its timeline in the robot's time`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val test =
            folder.test(
                "fast.test.kts",
                "${folder.examples}/localisation.coord.kts",
                """
            always { component("odometry0").state() == ACTIVE && component("gyro0").state() == ACTIVE }
            scenario("the laser breaks for good") {
                at(6.seconds) { breakDown("laser0") }
                expect(within = 10.seconds) { component("odo_localise0").state() == ACTIVE }
                expectLog("laser0 could not be reset")
            }
            """,
            )
        val result = runBlocking {
            CoordinatorTestRunner(1, speed = 10.0).let { it.runAll(it.files(listOf(test))) }.single()
        }

        assertTrue(result.passed, (TestReport.failures(result) + TestReport.timeline(result)).joinToString("\n"))
        // Six seconds of the robot's time before the fault alone, so at its clock the run takes longer than that. The
        // recovery's CORBA calls take host time whatever the speed: its deadline allows for a busy machine.
        assertTrue(result.duration < 6.seconds, "took ${result.duration}")
        val timeline = result.timeline.joinToString("\n")
        val fault = result.timeline.firstOrNull { it.kind == TimelineEntry.Kind.FAULT }
        assertTrue(fault != null && fault.at >= 6.seconds && fault.at < 6.5.seconds, timeline)
        // The laser's ERROR, seen on the tree's clock as the robot would see it: just after the fault.
        val error = result.timeline.firstOrNull { it.text == "laser0.rtc ACTIVE -> ERROR" }
        assertTrue(error != null && error.at >= fault!!.at && error.at < fault.at + 1.seconds, timeline)
    }

    @Test
    fun `a failing expect names its line and shows what each read of its condition returned at the deadline`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val wrong =
            folder.test(
                "wrong.test.kts",
                "${folder.examples}/localisation.coord.kts",
                """
            at(1.seconds) { breakDown("laser0") }
            expect(within = 3.seconds) { component("gyro0").state() == ERROR && modeOf("none") == null }
            """,
            )
        val result = run(wrong).single()
        val failure = result.failures.single()
        assertEquals("$wrong:4:1", failure.at)
        assertEquals(
            "expected component(\"gyro0\").state() == ERROR && modeOf(\"none\") == null within 3s, but it did not hold",
            failure.message,
        )
        assertEquals(listOf("component(\"gyro0\").state() was ACTIVE"), failure.details)
        val timeline = result.timeline.map { it.kind to it.text }
        assertTrue(TimelineEntry.Kind.FAULT to "breakDown laser0" in timeline, timeline.toString())
        assertTrue(TimelineEntry.Kind.EVENT to "laser0.rtc ACTIVE -> ERROR" in timeline, timeline.toString())
        assertTrue(
            timeline.any { it.first == TimelineEntry.Kind.LOG && "laser0 could not be reset" in it.second },
            timeline.toString(),
        )
    }

    @Test
    fun `a failing expectMode says which mode the machine was in and how it got there`(@TempDir directory: Path) {
        val folder = TestFolder(directory)
        val test =
            folder.test(
                "modes.test.kts",
                "${folder.examples}/modes.coord.kts",
                "expectMode(\"localisation\", \"degraded\", within = 1.seconds)",
            )
        val failure = run(test).single().failures.single()
        assertEquals(
            "$test:3:1: expected mode machine localisation in mode degraded within 1s, but it was in laser",
            failure.toString(),
        )
        assertEquals(listOf("(start) -> localisation/laser on start"), failure.details)
    }

    @Test
    fun `expectNoRestartsOf fails for each component a supervisor started again, the failed one and those restarted with it`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val test =
            folder.test(
                "restarts.test.kts",
                "${folder.examples}/supervision.coord.kts",
                """
            at(1.seconds) { fail("laser0") }
            expectLog("restForOne: restarting", within = 5.seconds)
            expect(within = 5.seconds) { component("laser0").state() == ACTIVE && component("laser_localise0").state() == ACTIVE }
            expectNoRestartsOf("laser0")
            expectNoRestartsOf("laser_localise0.rtc")
            expectNoRestartsOf("odometry0")
            """,
            )
        assertEquals(
            listOf(
                "$test:6:1: expected no restarts of laser0, but a supervisor restarted it 1 time(s)",
                "$test:7:1: expected no restarts of laser_localise0, but a supervisor restarted it 1 time(s)",
            ),
            run(test).single().failures.map { it.toString() },
        )
    }
}
