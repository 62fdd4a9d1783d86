package org.rtcoord.sim.test

import java.nio.file.Path
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/**
 * `meanwhile { }`: faults applied at their times alongside the steps, whatever step the timeline waits on;
 * `loseConnectors` among them.
 */
class MeanwhileTest {
    @Test
    fun `meanwhile faults apply at their times while a step waits, and a lost connector is gone at both ends`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val test =
            folder.test(
                "meanwhile.test.kts",
                "${folder.examples}/localisation.coord.kts",
                """
            scenario("the laser's connector is lost while an expectation waits") {
                expect { component("laser_localise0").snapshot().ports.first { it.name == "laser" }.connectors.size == 1 }
                meanwhile { at(500.milliseconds) { loseConnectors("laser0") } }
                expect(within = 5.seconds) {
                    component("laser0").snapshot().ports.all { it.connectors.isEmpty() } &&
                        component("laser_localise0").snapshot().ports.first { it.name == "laser" }.connectors.isEmpty()
                }
                expect { component("laser_localise0").snapshot().ports.first { it.name == "odo" }.connectors.size == 1 }
            }
            scenario("a meanwhile fault that cannot be applied fails at its line") {
                meanwhile {
                    at(200.milliseconds) { fail("ghost0") }
                }
                expect(within = 3.seconds) { component("laser0").state() == ERROR }
            }
            """,
            )
        val (lost, ghost) = runBlocking { CoordinatorTestRunner().let { it.runAll(it.files(listOf(test))) } }
        assertTrue(lost.passed, TestReport.failures(lost).joinToString("\n"))
        assertTrue(lost.timeline.any { it.kind == TimelineEntry.Kind.FAULT && it.text == "loseConnectors laser0" })
        val failure = ghost.failures.single()
        assertEquals("$test:14:9", failure.at)
        assertTrue(failure.message.startsWith("at 200ms: no component ghost0 in the simulated system"), failure.message)
    }
}
