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
}
