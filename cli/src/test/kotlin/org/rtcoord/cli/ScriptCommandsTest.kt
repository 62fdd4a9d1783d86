package org.rtcoord.cli

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import RTC.RTObjectHelper
import com.github.ajalt.clikt.testing.CliktCommandTestResult
import org.omg.CosNaming.NamingContextExtHelper
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.FixtureRuntime
import org.rtcoord.fixtures.Scenarios
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.naming.NamingService
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.Socket
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CompletableFuture

/** `check`, `run` and `demo`: the commands that compile and run coordinator scripts. */
class ScriptCommandsTest {
    @TempDir
    lateinit var directory: Path

    private fun script(name: String, text: String): Path = directory.resolve(name).also { Files.writeString(it, text) }

    @Test
    fun `check compiles scripts, lists what they declare and reports errors as file, line and column`() {
        val good = script("good.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n")
        val bad = script("bad.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) {\n    resett()\n}\n")
        assertEquals("$good: compiles\n  on laser0.rtc enters ERROR\n", runRtcoord("check", good.toString()).ok())

        val result = runRtcoord("check", good.toString(), bad.toString())
        assertEquals(1, result.statusCode)
        assertEquals("$good: compiles\n  on laser0.rtc enters ERROR\n", result.stdout)
        assertTrue(result.stderr.startsWith("$bad:2:5: ") && "resett" in result.stderr, result.stderr)
    }

    @Test
    fun `check with a name server reports each component, port and parameter the live system lacks, with line and column`() {
        Localisation().use { localisation ->
            val wrong = script(
                "wrong.coord.kts",
                "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n" +
                    "on(component(\"lazer0.rtc\")).state(ERROR) { reset() }\n" +
                    "on(port(\"laser0.rtc:scan\")).disconnected { }\n" +
                    "on(component(\"laser_localise0.rtc\")).configParam(\"gian\") { _, _ -> }\n",
            )
            val result = runRtcoord("-n", localisation.naming.address, "check", wrong.toString())
            assertEquals(1, result.statusCode, result.output)
            val errors = result.stderr.lines().filter { it.isNotEmpty() }
            assertEquals(listOf("$wrong:2:14: lazer0.rtc", "$wrong:3:9: laser0.rtc:scan", "$wrong:4:50: gian"), errors.map { it.substringBefore(": ", "").let { at -> "$at: " + it.removePrefix("$at: ").substringBefore(": ") } }, result.stderr)
            assertTrue(errors[0].endsWith("did you mean laser0.rtc?"), errors[0])
            assertTrue(errors[2].endsWith("has no parameter 'gian' (parameters: fail, gain)"), errors[2])

            val good = script("good-live.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n")
            assertTrue(runRtcoord("-n", localisation.naming.address, "check", good.toString()).ok().contains("everything it names is there"))
        }
    }

    @Test
    fun `run coordinates until --for elapses, then detaches its observers`() {
        Localisation().use { localisation ->
            val gyro = localisation.system.component("gyro0")
            val restart = script("restart.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) {\n    reset()\n    activate()\n}\n")
            val run = runWatchingGyro(localisation, restart)

            gyro.fail()
            await("the rule to bring gyro0 back") { run.isDone || (gyro.state == RTC.LifeCycleState.ACTIVE_STATE && "activate" in runLog(run)) }
            val result = run.get()
            assertEquals(0, result.statusCode, result.stderr)
            assertTrue("rule 'gyro0.rtc enters ERROR' fired" in result.stdout, result.stdout)
            assertTrue(Regex("""\d\d:\d\d:\d\d\.\d{3} reset /""").containsMatchIn(result.stdout), result.stdout)
            val watched = Regex("""\d\d:\d\d:\d\d\.\d{3} /\S+/gyro0\.rtc watched: pushed by its OpenRTM::ComponentObserver, heartbeat every 1s\n""")
            assertEquals(1, watched.findAll(result.stdout).count(), result.stdout)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, gyro.state)
            assertEquals(emptySet<String>(), gyro.observerIds)
        }
    }

    @Test
    fun `check lists a machine's modes and rejects a machine that cannot run`() {
        val machine = script(
            "modes.coord.kts",
            """
            modes("gyro") {
                initial("up")
                mode("up") {
                    network { active("gyro0") }
                    on(component("gyro0")).state(ERROR) goTo "down"
                }
                mode("down") {
                    entry { reset() }
                    on(component("gyro0")).state(INACTIVE) goTo "up"
                }
            }
            """.trimIndent(),
        )
        assertEquals(
            """
            $machine: compiles
              modes gyro, initially up
                mode up
                  network: active gyro0.rtc
                  on gyro0 enters ERROR -> down
                mode down, entry
                  on gyro0 enters INACTIVE -> up

            """.trimIndent(),
            runRtcoord("check", machine.toString()).ok(),
        )

        val unreachable = script("unreachable.coord.kts", "modes(\"gyro\") {\n    initial(\"up\")\n    mode(\"up\")\n    mode(\"down\")\n}\n")
        val result = runRtcoord("check", unreachable.toString())
        assertEquals(1, result.statusCode)
        assertEquals("$unreachable:1:1: machine 'gyro': mode 'gyro/down' is unreachable: no transition leads to it or into it\n", result.stderr)
    }

    @Test
    fun `run prints each mode transition`() {
        Localisation().use { localisation ->
            val gyro = localisation.system.component("gyro0")
            val modes = script(
                "gyro.coord.kts",
                """
                modes("gyro") {
                    initial("up")
                    mode("up") { on(component("gyro0.rtc")).state(ERROR) goTo "down" }
                    mode("down") {
                        entry { component("gyro0.rtc").reset() }
                        network { active("gyro0") }
                        on(done) goTo "up"
                    }
                }
                """.trimIndent(),
            )
            val run = runWatchingGyro(localisation, modes)

            gyro.fail()
            val result = run.get()
            assertEquals(0, result.statusCode, result.stderr)
            for (line in listOf("mode gyro: starts in gyro/up", "mode gyro/up -> gyro/down on gyro0.rtc enters ERROR", "mode gyro/down -> gyro/up on done")) {
                assertTrue(Regex("""\d\d:\d\d:\d\d\.\d{3} ${Regex.escape(line)}\n""").containsMatchIn(result.stdout), result.stdout)
            }
            assertTrue("stopped; 0 handler failures; 0 failed actions; gyro in gyro/up, 0 events no transition took" in result.stdout, result.stdout)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, gyro.state)
        }
    }

    @Test
    fun `run says once that a slave manager died, naming the components that went with it`() {
        Localisation().use { localisation ->
            val master = localisation.system.master!!.runtime.orb.corbaloc("manager")
            FixtureProcess.start("--naming", localisation.naming.address, "--scenario", "component:hosted0", "--master", master).use { process ->
                val rule = script("hosted.coord.kts", "on(component(\"hosted0.rtc\")).state(ERROR) { reset() }\n")
                val run = CompletableFuture.supplyAsync { runRtcoord("-n", localisation.naming.address, "run", "--for", "15s", rule.toString()) }
                val orb = localisation.system.runtime.orb.orb
                val hosted = RTObjectHelper.narrow(
                    NamingContextExtHelper.narrow(orb.string_to_object(localisation.naming.corbaloc)).resolve_str("${FixtureRuntime.hostContext}/hosted0.rtc"),
                )
                await("the coordinator to observe hosted0", timeout = kotlin.time.Duration.parse("60s")) {
                    hosted.get_service_profiles().any { it.id.startsWith("rtcoord-observer-") }
                }
                process.kill()
                val result = run.get()
                assertEquals(0, result.statusCode, result.stderr)
                val died = Regex("""\d\d:\d\d:\d\d\.\d{3} /\S+/manager_${process.pid} manager stopped answering \(.*\); its components went with it: hosted0\.rtc\n""")
                assertEquals(1, died.findAll(result.stdout).count(), result.stdout)
            }
        }
    }

    @Test
    fun `run says when its name server stops answering and when it answers again`() {
        var naming = NamingService.start()
        try {
            Scenarios.localisation(naming.corbaloc).use { system ->
                val rule = script("gyro.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n")
                val run = CompletableFuture.supplyAsync { runRtcoord("-n", naming.address, "run", "--for", "10s", rule.toString()) }
                await("the coordinator to observe gyro0", timeout = kotlin.time.Duration.parse("60s")) { system.component("gyro0").observerIds.isNotEmpty() }
                val saved = naming.snapshot()
                naming.close()
                // The run's output is read at its end: the outage lasts three of its one-second checks.
                Thread.sleep(3_000)
                naming = NamingService.start(naming.port, saved)
                val result = run.get()
                assertEquals(0, result.statusCode, result.stderr)
                val lost = Regex("""\d\d:\d\d:\d\d\.\d{3} /\Q${naming.address}\E name server unreachable \(.+\n""")
                val back = Regex("""\d\d:\d\d:\d\d\.\d{3} /\Q${naming.address}\E name server answers again, after \d+\.\d+ s\n""")
                assertEquals(1, lost.findAll(result.stdout).count(), result.stdout)
                assertEquals(1, back.findAll(result.stdout).count(), result.stdout)
            }
        } finally {
            naming.close()
        }
    }

    @Test
    fun `run waits for a name server that does not answer at start, or exits 1 with --require-name-servers`() {
        val rule = script("laser.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n")
        // Bound and never listening: connections are refused for as long as the test holds the port.
        Socket().use { reserved ->
            reserved.bind(InetSocketAddress(InetAddress.getLoopbackAddress(), 0))
            val server = "127.0.0.1:${reserved.localPort}"
            val waited = runRtcoord("-n", server, "run", "--for", "2s", rule.toString())
            assertEquals(0, waited.statusCode, waited.stderr)
            val said = Regex("""\d\d:\d\d:\d\d\.\d{3} name server \Q$server\E unreachable \(.+\); trying again every 1s\n""")
            assertEquals(1, said.findAll(waited.stdout).count(), waited.stdout)
            assertTrue("no such component" !in waited.stdout + waited.stderr, waited.stdout + waited.stderr)

            val refused = runRtcoord("-n", server, "run", "--require-name-servers", rule.toString())
            assertEquals(1, refused.statusCode)
            assertTrue(refused.stderr.startsWith("rtcoord: name server $server: unreachable"), refused.stderr)
        }
    }

    @Test
    fun `run says which actions failed, and which only as a best effort`() {
        Localisation().use { localisation ->
            val gyro = localisation.system.component("gyro0")
            val restart = script("broken.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) {\n    attempt { reset() }\n    reset()\n}\n")
            val run = runWatchingGyro(localisation, restart)

            gyro.breakDown()
            val result = run.get()
            assertEquals(0, result.statusCode, result.stderr)
            val path = localisation.path("gyro0.rtc")
            assertTrue("stopped; 1 handler failures; 2 failed actions\n" in result.stdout, result.stdout)
            assertTrue("  failed: reset $path: reset failed: RTC_ERROR (in context 0) (attempted, went on)\n" in result.stdout, result.stdout)
            assertTrue("  failed: reset $path: reset failed: RTC_ERROR (in context 0) (stopped its handler)\n" in result.stdout, result.stdout)
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
        assertTrue("laser0 could not be reset (reset failed: RTC_ERROR (in context 0)): it stays in ERROR" in result.stdout, result.stdout)
    }

    /** What [run] printed so far, once it finished; empty while it runs (the harness hands it over at the end). */
    private fun runLog(run: CompletableFuture<com.github.ajalt.clikt.testing.CliktCommandTestResult>): String =
        if (run.isDone) run.get().stdout else ""

    /** Starts `rtcoord run --for 8s SCRIPT` in the background and waits until the coordinator observes gyro0. */
    private fun runWatchingGyro(localisation: Localisation, script: Path): CompletableFuture<CliktCommandTestResult> {
        val run = CompletableFuture.supplyAsync { runRtcoord("-n", localisation.naming.address, "run", "--for", "8s", script.toString()) }
        await("the coordinator to observe gyro0", timeout = kotlin.time.Duration.parse("60s")) { localisation.system.component("gyro0").observerIds.isNotEmpty() }
        return run
    }
}
