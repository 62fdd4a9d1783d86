package org.rtcoord.dsl

import java.nio.file.Files
import java.nio.file.Path
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.fixtures.await

/**
 * What a script's handlers can call beyond actions, run from script files: start and stop, waiting, peers, and where
 * failures are.
 */
class ScriptingApiTest : CoordinatedSystem() {
    @TempDir lateinit var directory: Path

    private fun load(name: String, text: String): Coordinator {
        val file = directory.resolve(name).also { Files.writeString(it, text.trimIndent() + "\n") }
        return Coordinator(tree, runBlocking { ScriptHost(directory.resolve("cache")).load(file, host = config) }) {
            onLogLine(it)
        }
    }

    @Test
    fun `onStart runs once at the start, onStop at the stop, await waits for a condition or fails at its deadline at its line`():
        Unit = runBlocking {
        load(
                "start.coord.kts",
                """
            onStart {
                log("laser0:laser feeds ${'$'}{port("laser0.rtc:laser").peers()}")
                component("gyro0.rtc").deactivate()
                delay(10.milliseconds)
                await(5.seconds) { component("gyro0.rtc").state() == INACTIVE }
                log("gyro0 stopped")
                await(300.milliseconds) { component("gyro0.rtc").state() == ACTIVE }
            }
            onStop {
                component("gyro0.rtc").activate()
                log("gyro0 started again")
            }
            """,
            )
            .use { coordinator ->
                coordinator.start()
                await("onStart to fail at its second await") { coordinator.failures == 1 }
                assertTrue("laser0:laser feeds [${path("laser_localise0.rtc:laser")}]" in log, log.joinToString("\n"))
                assertTrue("gyro0 stopped" in log, log.joinToString("\n"))
                val failure = coordinator.handlerFailures.single()
                assertEquals(
                    "on start failed at start.coord.kts:7: TimedOut: the condition did not hold within 300ms",
                    failure.toString(),
                )
                assertEquals(RTC.LifeCycleState.INACTIVE_STATE, system.component("gyro0").state)

                coordinator.stop()
                assertEquals(RTC.LifeCycleState.ACTIVE_STATE, system.component("gyro0").state)
                assertEquals("gyro0 started again", log.last())
            }
    }

    @Test
    fun `a handler that throws is reported at the script's innermost line, with its type and message and the script's frames`():
        Unit = runBlocking {
        load(
                "parse.coord.kts",
                """
            fun parse(text: String) = text.toInt()
            after(0.seconds) {
                log("parsing")
                parse("three")
            }
            """,
            )
            .use { coordinator ->
                coordinator.start()
                await("the timer to fail") { coordinator.failures == 1 }
                val failure = coordinator.handlerFailures.single()
                assertEquals("timer after 0s", failure.subject)
                assertEquals("parse.coord.kts:1", failure.at)
                assertEquals("NumberFormatException", failure.type)
                assertEquals("For input string: \"three\"", failure.message)
                assertEquals(
                    listOf("parse.coord.kts:1", "parse.coord.kts:4"),
                    failure.scriptFrames.map { it.substringBefore(" (") },
                )
                assertTrue(
                    "timer after 0s failed at parse.coord.kts:1: NumberFormatException: For input string: \"three\"" in
                        log,
                    log.joinToString("\n"),
                )
            }
    }
}
