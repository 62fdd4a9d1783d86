package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/**
 * What fails a test besides its expectations: a handler of the coordinator that fails, a rule naming what the system
 * lacks, a test that does not compile or names files that are not there. Each is a failed result with where and why,
 * and never keeps the run's other tests from running and reporting.
 */
class NoSilentPassTest {
    @Test
    fun `a failing handler fails the test at the coordinator's line unless the scenario expects it, and the others still run`(
        @TempDir directory: Path
    ) {
        val folder = TestFolder(directory)
        val boom =
            folder.write("a/boom.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) {\n    error(\"boom\")\n}")
        val unexpected =
            folder.test(
                "a/transient.test.kts",
                boom.toString(),
                """
            at(1.seconds) { fail("laser0") }
            expect(within = 5.seconds) { component("laser0").state() == ERROR }
            """,
            )
        val expected =
            folder.test(
                "b/transient.test.kts",
                boom.toString(),
                """
            at(1.seconds) { fail("laser0") }
            expectHandlerFailure("boom", within = 5.seconds)
            """,
            )
        val lidar =
            folder.write(
                "c/lidar.coord.kts",
                "val limit = 3\non(component(\"lidar0.rtc\")).state(ERROR) { log(\"lidar\") }",
            )
        val missing =
            folder.test("c/transient.test.kts", lidar.toString(), "expect { component(\"laser0\").state() == ACTIVE }")

        val runner = CoordinatorTestRunner()
        val files = runner.files(listOf(directory))
        assertEquals(listOf("a/transient", "b/transient", "c/transient"), files.map { it.name })
        val results = runBlocking { runner.runAll(files) }

        val handler = results[0].failures.single()
        assertEquals("$boom:2", handler.at)
        assertEquals("rule 'laser0.rtc enters ERROR' failed: IllegalStateException: boom", handler.message)
        assertTrue(handler.details.first().contains("expectHandlerFailure(\"boom\")"), handler.details.toString())
        assertTrue(results[1].passed, TestReport.failures(results[1]).joinToString("\n"))

        val target = results[2].failures.single()
        assertEquals("$lidar:2:14", target.at)
        assertTrue(target.message.startsWith("lidar0.rtc: no such component"), target.message)
        assertEquals("the coordinator of $missing:2:1 cannot start", target.details.first())

        val written =
            JUnitXml.write(results, directory.resolve("junit")).map {
                directory.resolve("junit").relativize(it).toString()
            }
        assertEquals(listOf("TEST-a.transient.xml", "TEST-b.transient.xml", "TEST-c.transient.xml"), written)
        assertTrue(unexpected.toString().isNotEmpty() && expected.toString().isNotEmpty())
    }

    @Test
    fun `bad input is one line each where it is, and the test failed`(@TempDir directory: Path) {
        val folder = TestFolder(directory)
        val good = "${folder.examples}/localisation.coord.kts"
        val syntax =
            folder.write(
                "syntax.test.kts",
                "system(\"${folder.system}\")\ncoordinator(\"$good\")\nexpect { component(\"laser0\").state() == }",
            )
        val type = folder.test("type.test.kts", good, "at(1) { fail(\"laser0\") }")
        val noCoordinator = folder.test("nocoord.test.kts", "absent.coord.kts", "expect { true }")
        val noSystem = folder.write("nosystem.test.kts", "system(\"absent.xml\")\ncoordinator(\"$good\")")
        val broken = folder.write("broken.coord.kts", "on(component(\"laser0.rtc\")).stat(ERROR) { }")
        val badCoordinator = folder.test("badcoord.test.kts", broken.toString(), "expect { true }")
        val noMode =
            folder.test(
                "nomode.test.kts",
                "${folder.examples}/modes.coord.kts",
                "expectMode(\"localisation\", \"odometri\")",
            )

        val results = runBlocking {
            CoordinatorTestRunner().let { it.runAll(it.files(listOf(directory))) }
        }
            .associateBy { it.file.path }
        fun failure(file: Path) = results.getValue(file).failures.single().toString()

        assertTrue(failure(syntax).startsWith("$syntax:3:"), failure(syntax))
        assertTrue(
            failure(type).startsWith("$type:3:4: ") &&
                failure(type).endsWith("(hint: a duration has a unit: write 1.seconds (or 1.milliseconds, 1.minutes))"),
            failure(type),
        )
        assertEquals(
            "$noCoordinator:2:1: no such coordinator file: ${TestFiles.shown(directory.resolve("absent.coord.kts"))}",
            failure(noCoordinator),
        )
        assertEquals(
            "$noSystem:1:1: no such system file: ${TestFiles.shown(directory.resolve("absent.xml"))}",
            failure(noSystem),
        )
        assertTrue(failure(badCoordinator).startsWith("${TestFiles.shown(broken)}:1:"), failure(badCoordinator))
        assertEquals(
            "$noMode:3:1: no such mode 'odometri' in mode machine localisation (modes: laser, degraded, degraded/odometry, degraded/odometry/switching, " +
                "degraded/odometry/tracking, degraded/safe)",
            failure(noMode),
        )
        assertTrue(Files.exists(noSystem))
    }
}
