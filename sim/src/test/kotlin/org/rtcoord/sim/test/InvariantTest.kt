package org.rtcoord.sim.test

import java.nio.file.Path
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/** `always` and `never`: checked on every event from where they are written, failing at the first that breaks them. */
class InvariantTest {
    @Test
    fun `an invariant fails at the event that broke it, with its time, and one that holds passes`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val test =
            folder.test(
                "invariants.test.kts",
                "${folder.examples}/localisation.coord.kts",
                """
            always { component("gyro0").state() == ACTIVE }
            scenario("the localiser is switched") {
                never { component("laser_localise0").state() == INACTIVE }
                at(1.seconds) { breakDown("laser0") }
                expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
            }
            scenario("from a step on") {
                at(1.seconds) { breakDown("laser0") }
                expect(within = 5.seconds) { component("odo_localise0").state() == ACTIVE }
                never { component("laser_localise0").state() == ACTIVE || !component("odo_localise0").exists() }
                at(2.seconds) { repair("laser0") }
            }
            """,
            )
        val (broken, held) = runBlocking { CoordinatorTestRunner().let { it.runAll(it.files(listOf(test))) } }
        val failure = broken.failures.single()
        assertEquals("$test:5:5", failure.at)
        assertTrue(
            Regex(
                    """never \{ component\("laser_localise0"\)\.state\(\) == INACTIVE } broke at \d+\.\d{3} s, on event: laser_localise0\.rtc ACTIVE -> INACTIVE"""
                )
                .matches(failure.message),
            failure.message,
        )
        assertEquals(listOf("component(\"laser_localise0\").state() was INACTIVE"), failure.details)
        assertTrue(held.passed, TestReport.failures(held).joinToString("\n"))
    }

    @Test
    fun `a condition reads the components a glob matches, live and as each event left them`(@TempDir directory: Path) {
        val folder = TestFolder(directory)
        val test =
            folder.test(
                "globs.test.kts",
                "${folder.examples}/localisation.coord.kts",
                """
            scenario("one localiser at a time, whichever it is") {
                never { components("*_localise?").count { it.state() == ACTIVE } > 1 }
                at(1.seconds) { breakDown("laser0") }
                expect(within = 5.seconds) { components("odo_localise*").any { it.state() == ACTIVE } }
            }
            scenario("none yet") {
                expect(within = 1.seconds) { components("odo_localise*").isNotEmpty() }
            }
            """,
            )
        val (held, broken) = runBlocking { CoordinatorTestRunner().let { it.runAll(it.files(listOf(test))) } }
        assertTrue(held.passed, TestReport.failures(held).joinToString("\n"))
        assertEquals(listOf("components(\"odo_localise*\") was []"), broken.failures.single().details)
    }
}
