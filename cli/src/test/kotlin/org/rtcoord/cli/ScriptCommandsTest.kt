package org.rtcoord.cli

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.fixtures.await
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CompletableFuture

/** `check`, `run` and `demo`: the commands that compile and run coordinator scripts. */
class ScriptCommandsTest {
    @TempDir
    lateinit var directory: Path

    private fun script(name: String, text: String): Path = directory.resolve(name).also { Files.writeString(it, text) }

    @Test
    fun `check compiles scripts and reports errors as file, line and column`() {
        val good = script("good.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n")
        val bad = script("bad.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) {\n    resett()\n}\n")
        assertEquals("$good: compiles\n", runRtcoord("check", good.toString()).ok())

        val result = runRtcoord("check", good.toString(), bad.toString())
        assertEquals(1, result.statusCode)
        assertEquals("$good: compiles\n", result.stdout)
        assertTrue(result.stderr.startsWith("$bad:2:5: ") && "resett" in result.stderr, result.stderr)
    }

    @Test
    fun `run coordinates until --for elapses, then detaches its observers`() {
        Localisation().use { localisation ->
            val gyro = localisation.system.component("gyro0")
            val restart = script("restart.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) {\n    reset()\n    activate()\n}\n")
            val run = CompletableFuture.supplyAsync { runRtcoord("-n", localisation.naming.address, "run", "--for", "8s", restart.toString()) }
            await("the coordinator to observe gyro0", timeout = kotlin.time.Duration.parse("60s")) { gyro.observerIds.isNotEmpty() }

            gyro.fail()
            await("the rule to bring gyro0 back") { run.isDone || (gyro.state == RTC.LifeCycleState.ACTIVE_STATE && "activate" in runLog(run)) }
            val result = run.get()
            assertEquals(0, result.statusCode, result.stderr)
            assertTrue("rule 'gyro0.rtc enters ERROR' fired" in result.stdout, result.stdout)
            assertTrue(Regex("""\d\d:\d\d:\d\d\.\d{3} reset /""").containsMatchIn(result.stdout), result.stdout)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, gyro.state)
            assertEquals(emptySet<String>(), gyro.observerIds)
        }
    }

    @Test
    fun `run refuses a script that does not compile`() {
        val bad = script("bad.coord.kts", "on(component(\"x\")).state(ERRORR) { }\n")
        val result = runRtcoord("run", bad.toString())
        assertEquals(1, result.statusCode)
        assertTrue(result.stderr.startsWith("rtcoord: $bad:1:"), result.stderr)
    }

    @Test
    fun `demo ends in the expected state`() {
        val result = runRtcoord("demo")
        assertEquals(0, result.statusCode, result.stderr)
        assertTrue("coordinator: create odo_localise through" in result.stdout, result.stdout)
        assertTrue(Regex("""Recovered \d+ ms after the laser failed""").containsMatchIn(result.stdout), result.stdout)
    }

    /** What [run] printed so far, once it finished; empty while it runs (the harness hands it over at the end). */
    private fun runLog(run: CompletableFuture<com.github.ajalt.clikt.testing.CliktCommandTestResult>): String =
        if (run.isDone) run.get().stdout else ""
}
