package org.rtcoord.sim.explore

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNotEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.test.FaultKind
import org.rtcoord.sim.test.LoadedTest
import org.rtcoord.sim.test.TestFiles
import org.rtcoord.sim.test.TestLoader
import org.rtcoord.sim.test.TestScriptHost

/** What an exploration draws: the same schedule for the same seed and index, within what the test narrows it to. */
class ScheduleSpaceTest {
    private val examples = Paths.get("../examples").toAbsolutePath().normalize()

    private fun load(directory: Path, text: String): LoadedTest {
        val file = directory.resolve("space.test.kts")
        Files.writeString(
            file,
            "system(\"${examples.resolve("localisation.xml")}\")\ncoordinator(\"${examples.resolve("localisation.coord.kts")}\")\n" +
                text.trimIndent() +
                "\n",
        )
        return runBlocking { TestLoader(TestScriptHost(), ScriptHost()).load(TestFiles.find(listOf(file)).single()) }
    }

    @Test
    fun `the same seed and index draw the same schedule, every fault of the vocabulary on the system's components and managers`(
        @TempDir directory: Path
    ) {
        val test =
            load(directory, "at(3.seconds) { fail(\"laser0\") }\nexpect { component(\"gyro0\").state() == ACTIVE }")
        val space = ScheduleSpace(test, 3)
        val drawn = (0L until 300).map { space.draw(42, it) }
        assertEquals(drawn.map { it.toString() }, (0L until 300).map { ScheduleSpace(test, 3).draw(42, it).toString() })
        assertNotEquals(drawn.map { it.toString() }, (0L until 300).map { space.draw(43, it).toString() })
        assertEquals(FaultKind.entries.toSet(), drawn.flatMap { s -> s.faults.map { it.fault.kind } }.toSet())
        assertTrue(drawn.all { it.faults.size in 1..3 })
        // The window: from the start to where the timeline would end (the at step, then the expectation's deadline).
        assertTrue(drawn.all { s -> s.faults.all { it.time in 0.seconds..8.seconds } })
        assertTrue(drawn.any { s -> s.faults.any { it.time > 7.seconds } })
        assertEquals(
            setOf("manager", "manager_slave"),
            drawn
                .flatMap { s -> s.faults.filter { it.fault.kind == FaultKind.KILL_MANAGER }.map { it.fault.target } }
                .toSet(),
        )
        // Nothing is drawn on what an earlier fault of the schedule took away, and only what was broken is repaired.
        for (schedule in drawn) {
            schedule.faults.forEachIndexed { i, fault ->
                val before = schedule.faults.take(i).map { it.fault }
                assertTrue(
                    before.none { it.kind == FaultKind.EXIT && it.target == fault.fault.target },
                    schedule.toString(),
                )
                if (fault.fault.kind == FaultKind.REPAIR)
                    assertTrue(
                        before.any { it.kind.repairable && it.target == fault.fault.target },
                        schedule.toString(),
                    )
            }
        }
    }

    @Test
    fun `a test narrows the search to components, faults, a window, and excludes what is out of scope`(
        @TempDir directory: Path
    ) {
        val test =
            load(
                directory,
                """
            expect { component("gyro0").state() == ACTIVE }
            explore {
                components("laser0", "gyro0.rtc")
                window(1.seconds, 2.seconds)
                exclude { killManager(); exit("gyro0"); restartNaming() }
            }
            """,
            )
        val faults = (0L until 200).flatMap { ScheduleSpace(test, 2).draw(5, it).faults }
        assertTrue(faults.all { it.time in 1.seconds..2.seconds })
        assertTrue(faults.none { it.fault.kind == FaultKind.KILL_MANAGER || it.fault.kind == FaultKind.RESTART_NAMING })
        assertEquals(setOf("laser0", "gyro0"), faults.mapNotNull { it.fault.target }.toSet())
        assertTrue(faults.none { it.fault.kind == FaultKind.EXIT && it.fault.target == "gyro0" })
        assertTrue(faults.any { it.fault.kind == FaultKind.EXIT && it.fault.target == "laser0" })
    }
}
