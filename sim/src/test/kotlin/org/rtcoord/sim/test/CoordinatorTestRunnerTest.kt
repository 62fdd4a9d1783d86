package org.rtcoord.sim.test

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/** `*.test.kts` files run against systems simulated from a profile: the paper's scenario, and a wrong expectation. */
class CoordinatorTestRunnerTest {
    private val examples: Path = Paths.get("../examples").toAbsolutePath().normalize()

    @Test
    fun `the paper's scenario passes on the system simulated from the saved profile, and a wrong expectation fails with its line`(@TempDir directory: Path) {
        val wrong = directory.resolve("wrong.test.kts")
        Files.writeString(
            wrong,
            """
            system("${examples.resolve("localisation.xml")}")
            coordinator("${examples.resolve("localisation.coord.kts")}")
            at(1.seconds) { breakDown("laser0") }
            expect(within = 3.seconds) { component("gyro0").state() == ERROR }
            """.trimIndent(),
        )
        val results = runBlocking { CoordinatorTestRunner().runAll(listOf(examples.resolve("localisation.test.kts"), wrong)) }
        assertTrue(results[0].passed, results[0].failures.joinToString("\n"))
        assertEquals(1, results[1].failures.size, results[1].failures.toString())
        assertTrue(results[1].failures.single().startsWith("$wrong:4: expected the condition within 3s"), results[1].failures.single())

        val written = JUnitXml.write(results, directory.resolve("junit"))
        assertTrue(Files.readString(written[0]).contains("failures=\"0\""))
        assertTrue(Files.readString(written[1]).contains("failures=\"1\""))
    }

    @Test
    fun `expectNoRestartsOf fails for each component a supervisor started again, the failed one and those restarted with it`(@TempDir directory: Path) {
        val test = directory.resolve("restarts.test.kts")
        Files.writeString(
            test,
            """
            system("${examples.resolve("localisation.xml")}")
            coordinator("${examples.resolve("supervision.coord.kts")}")
            at(1.seconds) { fail("laser0") }
            expectLog("restForOne: restarting", within = 5.seconds)
            expect(within = 5.seconds) { component("laser0").state() == ACTIVE && component("laser_localise0").state() == ACTIVE }
            expectNoRestartsOf("laser0")
            expectNoRestartsOf("laser_localise0.rtc")
            expectNoRestartsOf("odometry0")
            """.trimIndent(),
        )
        val result = runBlocking { CoordinatorTestRunner().runAll(listOf(test)) }.single()
        assertEquals(
            listOf(
                "$test:6: expected no restarts of laser0, but a supervisor restarted it 1 time(s)",
                "$test:7: expected no restarts of laser_localise0, but a supervisor restarted it 1 time(s)",
            ),
            result.failures,
        )
    }
}
