package org.rtcoord.cli

import RTC.RTObjectHelper
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.Socket
import java.nio.file.Files
import java.nio.file.Path
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.omg.CosNaming.NamingContextExtHelper
import org.rtcoord.fixtures.DeadPort
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/** `check`, `run` and `demo`: the commands that compile and run coordinator scripts. */
class ScriptCommandsTest {
    @TempDir lateinit var directory: Path

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
            val wrong =
                script(
                    "wrong.coord.kts",
                    "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n" +
                        "on(component(\"lazer0.rtc\")).state(ERROR) { reset() }\n" +
                        "on(port(\"laser0.rtc:scan\")).disconnected { }\n" +
                        "on(component(\"laser_localise0.rtc\")).configParam(\"gian\") { _, _ -> }\n",
                )
            val result = runRtcoord("-n", localisation.naming.address, "check", wrong.toString())
            assertEquals(1, result.statusCode, result.output)
            val errors = result.stderr.lines().filter { it.isNotEmpty() }
            assertEquals(
                listOf("$wrong:2:14: lazer0.rtc", "$wrong:3:9: laser0.rtc:scan", "$wrong:4:50: gian"),
                errors.map {
                    it.substringBefore(": ", "").let { at -> "$at: " + it.removePrefix("$at: ").substringBefore(": ") }
                },
                result.stderr,
            )
            assertTrue(errors[0].endsWith("did you mean laser0.rtc?"), errors[0])
            assertTrue(errors[2].endsWith("has no parameter 'gian' (parameters: fail, gain)"), errors[2])

            val good = script("good-live.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n")
            assertTrue(
                runRtcoord("-n", localisation.naming.address, "check", good.toString())
                    .ok()
                    .contains("everything it names is there")
            )
        }
    }

    @Test
    fun `check with a name server checks what handlers and data rules name, and says what the script creates and what it computes`() {
        Localisation().use { localisation ->
            val handlers =
                script(
                    "handlers.coord.kts",
                    """
                    val target = args.firstOrNull() ?: "gyro0.rtc"
                    on(port("laser0.rtc:scan")).silentFor(500.milliseconds) { log("quiet") }
                    every(5.seconds) {
                        component("lazer0.rtc").reset()
                        manager().create("odo_localise")
                        component("odo_localise0.rtc").activate()
                        component(target).reset()
                        manager().create("odo_lokalise")
                    }
                    """
                        .trimIndent() + "\n",
                )
            val result = runRtcoord("-n", localisation.naming.address, "check", handlers.toString())
            assertEquals(1, result.statusCode, result.output)
            val errors = result.stderr.lines().filter { it.isNotEmpty() }
            assertEquals(
                listOf("$handlers:2:9: laser0.rtc:scan", "$handlers:4:15: lazer0.rtc", "$handlers:8:22: odo_lokalise"),
                errors.map { it.split(": ").take(2).joinToString(": ") },
                result.stderr,
            )
            assertTrue(errors[1].endsWith("did you mean laser0.rtc?"), errors[1])
            assertTrue(
                errors[2].contains("no manager can create or load 'odo_lokalise' (factories: ") &&
                    "odo_localise" in errors[2],
                errors[2],
            )
            assertTrue(
                "$handlers:6:15: odo_localise0.rtc: created by the script at $handlers:5\n" in result.stdout,
                result.stdout,
            )
            assertTrue(
                "$handlers: not checked: 1 name computed as the script runs, at 7:15 (target)\n" in result.stdout,
                result.stdout,
            )
            assertTrue("everything it names is there" !in result.stdout, result.stdout)
        }
    }

    @Test
    fun `check with a name server that does not answer is an error, not a pass`() {
        val good = script("good.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n")
        val server = deadNameServer()
        val result = runRtcoord("-n", server, "check", good.toString())
        assertEquals(1, result.statusCode, result.output)
        assertTrue(result.stderr.startsWith("$good: its names cannot be checked: name server $server: "), result.stderr)
        assertTrue("everything it names is there" !in result.stdout, result.stdout)
    }

    @Test
    fun `every example passes check against the fixtures, modes creating what its network names`() {
        Localisation().use { localisation ->
            val examples =
                Files.list(Path.of("..", "examples")).use { files ->
                    files.filter { it.toString().endsWith(".coord.kts") }.sorted().toList()
                }
            assertTrue(examples.size >= 6, examples.toString())
            for (example in examples) {
                val output = runRtcoord("-n", localisation.naming.address, "check", example.toString()).ok()
                assertTrue("$example: everything it names is there" in output, output)
            }
            val modes = runRtcoord("-n", localisation.naming.address, "check", "../examples/modes.coord.kts").ok()
            assertTrue(
                Regex(
                        """modes\.coord\.kts:\d+:\d+: odo_localise0\.rtc: created by the script at \S+modes\.coord\.kts:\d+"""
                    )
                    .containsMatchIn(modes),
                modes,
            )
        }
    }

    @Test
    fun `run names the line, type and message of each handler failure, and the summary lists them`() {
        Localisation().use { localisation ->
            val failing =
                script(
                    "three.coord.kts",
                    "after(0.seconds) {\n    log(\"parsing\")\n    val n = \"three\".toInt()\n}\nafter(0.seconds) {\n    component(\"lazer0.rtc\").deactivate()\n}\n",
                )
            val result =
                runRtcoordUntil(
                    "-n",
                    localisation.naming.address,
                    "run",
                    failing.toString(),
                    what = "the second handler's failure",
                ) {
                    "failed at three.coord.kts:6" in it
                }
            assertEquals(0, result.statusCode, result.output)
            val thrown =
                "timer after 0s failed at three.coord.kts:3: NumberFormatException: For input string: \"three\""
            assertTrue(
                Regex("""\d\d:\d\d:\d\d\.\d{3} ${Regex.escape(thrown)}\n""").containsMatchIn(result.stdout),
                result.stdout,
            )
            val lookup = "timer after 0s failed at three.coord.kts:6: NotFoundException: lazer0.rtc: "
            assertTrue(lookup in result.stdout, result.stdout)
            assertTrue("stopped by SIGINT; 2 handler failures; 1 failed action\n" in result.stdout, result.stdout)
            assertTrue("\n  $thrown\n" in result.stdout, result.stdout)
            assertTrue("\n  $lookup" in result.stdout, result.stdout)
            assertTrue("\n  failed action: deactivate lazer0.rtc: " in result.stdout, result.stdout)
        }
    }

    @Test
    fun `compile makes a jar that run starts without the script, and run refuses a jar that is not a coordinator`() {
        Localisation().use { localisation ->
            val source = script("reset.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) { reset() }\n")
            val jar = directory.resolve("reset.jar")
            assertEquals(
                "$source: compiled into $jar\n",
                runRtcoord("compile", source.toString(), "-o", jar.toString()).ok(),
            )
            Files.delete(source)
            val run = runRtcoord("-n", localisation.naming.address, "run", "--for", "1ms", jar.toString())
            assertEquals(0, run.statusCode, run.output)
            assertTrue("coordinating:\n  on laser0.rtc enters ERROR\n" in run.stdout, run.stdout)

            val plain = Files.writeString(directory.resolve("plain.jar"), "not a jar\n")
            val refused =
                runRtcoord("-n", localisation.naming.address, "run", "--for", "1ms", plain.toString()).failure()
            assertTrue(refused.startsWith("rtcoord: $plain: not a compiled coordinator"), refused)
        }
    }

    @Test
    fun `run says where a misspelt target is, warns of rules that can never fire, and refuses them with --strict`() {
        Localisation().use { localisation ->
            val misspelt = script("misspelt.coord.kts", "on(component(\"lazer0.rtc\")).state(ERROR) { reset() }\n")
            val refused =
                runRtcoord("-n", localisation.naming.address, "run", "--for", "1s", misspelt.toString()).failure()
            assertTrue(
                refused.startsWith("rtcoord: $misspelt:1:14: lazer0.rtc: ") &&
                    refused.endsWith("did you mean laser0.rtc?"),
                refused,
            )

            val silent =
                script(
                    "silent.coord.kts",
                    "on(component(\"laser0.rtc\")).state(ERROR) { }\non(port(\"laser0.rtc:scan\")).silentFor(1.seconds) { }\n",
                )
            val noPort = runRtcoord("-n", localisation.naming.address, "run", "--for", "1s", silent.toString())
            assertEquals(1, noPort.statusCode, noPort.output)
            assertEquals("rtcoord: $silent:2:9: laser0.rtc:scan: no such port (ports: laser)\n", noPort.stderr)

            val never =
                script("never.coord.kts", "on(component(\"laser_localise0.rtc\")).configParam(\"gian\") { _, _ -> }\n")
            val warned =
                runRtcoordUntil(
                    "-n",
                    localisation.naming.address,
                    "run",
                    never.toString(),
                    what = "the coordinator started",
                ) {
                    "coordinating:" in it
                }
            assertEquals(0, warned.statusCode, warned.output)
            assertEquals(
                "rtcoord: warning: $never:1:50: gian: laser_localise0.rtc has no parameter 'gian' (parameters: fail, gain); what names it can never fire\n",
                warned.stderr,
            )
            val strict = runRtcoord("-n", localisation.naming.address, "run", "--strict", never.toString())
            assertEquals(1, strict.statusCode, strict.output)
            assertTrue(
                strict.stderr.endsWith("rtcoord: $never: 1 rule or mode can never fire (--strict)\n"),
                strict.stderr,
            )
        }
    }

    @Test
    fun `run coordinates until interrupted, then detaches its observers`() {
        Localisation().use { localisation ->
            val gyro = localisation.system.component("gyro0")
            val restart =
                script(
                    "restart.coord.kts",
                    "on(component(\"gyro0.rtc\")).state(ERROR) {\n    reset()\n    activate()\n}\n",
                )
            val run = runWatchingGyro(localisation, restart)

            gyro.fail()
            run.awaitLine("the rule's activation") { Regex("""\d\d:\d\d:\d\d\.\d{3} activate /""").containsMatchIn(it) }
            await("gyro0 back") { gyro.state == RTC.LifeCycleState.ACTIVE_STATE }
            val result = run.stop()
            assertEquals(0, result.statusCode, result.stderr)
            assertTrue("stopped by SIGINT; 0 handler failures; 0 failed actions\n" in result.stdout, result.stdout)
            assertTrue("rule 'gyro0.rtc enters ERROR' fired" in result.stdout, result.stdout)
            assertTrue(Regex("""\d\d:\d\d:\d\d\.\d{3} reset /""").containsMatchIn(result.stdout), result.stdout)
            val watched =
                Regex(
                    """\d\d:\d\d:\d\d\.\d{3} /\S+/gyro0\.rtc watched: pushed by its OpenRTM::ComponentObserver, heartbeat every 1s\n"""
                )
            assertEquals(1, watched.findAll(result.stdout).count(), result.stdout)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, gyro.state)
            assertEquals(emptySet<String>(), gyro.observerIds)
        }
    }

    @Test
    fun `check lists a machine's modes and rejects a machine that cannot run`() {
        val machine =
            script(
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
                """
                    .trimIndent(),
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

            """
                .trimIndent(),
            runRtcoord("check", machine.toString()).ok(),
        )

        val unreachable =
            script(
                "unreachable.coord.kts",
                "modes(\"gyro\") {\n    initial(\"up\")\n    mode(\"up\")\n    mode(\"down\")\n}\n",
            )
        val result = runRtcoord("check", unreachable.toString())
        assertEquals(1, result.statusCode)
        assertEquals(
            "$unreachable:1:1: machine 'gyro': mode 'gyro/down' is unreachable: no transition leads to it or into it\n",
            result.stderr,
        )
    }

    @Test
    fun `run prints each mode transition`() {
        Localisation().use { localisation ->
            val gyro = localisation.system.component("gyro0")
            val modes =
                script(
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
                    """
                        .trimIndent(),
                )
            val run = runWatchingGyro(localisation, modes)

            gyro.fail()
            run.awaitLine("the machine back in gyro/up") { it.endsWith("mode gyro/down -> gyro/up on done") }
            val result = run.stop()
            assertEquals(0, result.statusCode, result.stderr)
            for (line in
                listOf(
                    "mode gyro: starts in gyro/up",
                    "mode gyro/up -> gyro/down on gyro0.rtc enters ERROR",
                    "mode gyro/down -> gyro/up on done",
                )) {
                assertTrue(
                    Regex("""\d\d:\d\d:\d\d\.\d{3} ${Regex.escape(line)}\n""").containsMatchIn(result.stdout),
                    result.stdout,
                )
            }
            assertTrue(
                "stopped by SIGINT; 0 handler failures; 0 failed actions; gyro in gyro/up, 0 events no transition took" in
                    result.stdout,
                result.stdout,
            )
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, gyro.state)
        }
    }

    @Test
    fun `run says once that a slave manager died, naming the components that went with it`() {
        Localisation().use { localisation ->
            val master = localisation.system.master!!.runtime.orb.corbaloc("manager")
            FixtureProcess.start(
                    "--naming",
                    localisation.naming.address,
                    "--scenario",
                    "component:hosted0",
                    "--master",
                    master,
                )
                .use { process ->
                    // The rule on gyro0 logs a marker: what the death had to say is printed before it.
                    val rule =
                        script(
                            "hosted.coord.kts",
                            "on(component(\"hosted0.rtc\")).state(ERROR) { reset() }\non(component(\"gyro0.rtc\")).state(INACTIVE) { log(\"marker\") }\n",
                        )
                    val run = RunningCommand("-n", localisation.naming.address, "run", rule.toString())
                    val orb = localisation.system.runtime.orb.orb
                    val hosted =
                        RTObjectHelper.narrow(
                            NamingContextExtHelper.narrow(orb.string_to_object(localisation.naming.corbaloc))
                                .resolve_str("${RuntimeProcess.hostContext}/hosted0.rtc")
                        )
                    await("the coordinator to observe hosted0", timeout = kotlin.time.Duration.parse("60s")) {
                        hosted.get_service_profiles().any { it.id.startsWith("rtcoord-observer-") }
                    }
                    process.kill()
                    run.awaitLine("the manager's death") { " manager stopped answering " in it }
                    runRtcoord("deact", localisation.path("gyro0.rtc")).ok()
                    run.awaitLine("the marker") { it.endsWith(" marker") }
                    val result = run.stop()
                    assertEquals(0, result.statusCode, result.stderr)
                    val died =
                        Regex(
                            """\d\d:\d\d:\d\d\.\d{3} /\S+/manager_${process.pid} manager stopped answering \(.*\); its components went with it: hosted0\.rtc\n"""
                        )
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
                val run = RunningCommand("-n", naming.address, "run", rule.toString())
                await("the coordinator to observe gyro0", timeout = kotlin.time.Duration.parse("60s")) {
                    system.component("gyro0").observerIds.isNotEmpty()
                }
                val saved = naming.snapshot()
                naming.close()
                run.awaitLine("the name server said unreachable") { " name server unreachable " in it }
                // Said once, not at each of the run's checks: the outage lasts three of them (each lists the root
                // context), counted where the name server listened.
                DeadPort(naming.address, system.runtime.orb.orb).use { port ->
                    await("three checks of the stopped name server", timeout = kotlin.time.Duration.parse("30s")) {
                        port.requests("list") >= 3
                    }
                }
                naming = NamingService.start(naming.port, saved)
                run.awaitLine("the name server said to answer again") { " name server answers again" in it }
                val result = run.stop()
                assertEquals(0, result.statusCode, result.stderr)
                val lost = Regex("""\d\d:\d\d:\d\d\.\d{3} /\Q${naming.address}\E name server unreachable \(.+\n""")
                val back =
                    Regex(
                        """\d\d:\d\d:\d\d\.\d{3} /\Q${naming.address}\E name server answers again, after \d+\.\d+ s\n"""
                    )
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
            val said =
                Regex("""\d\d:\d\d:\d\d\.\d{3} name server \Q$server\E unreachable \(.+\); trying again every 1s\n""")
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
            val restart =
                script(
                    "broken.coord.kts",
                    "on(component(\"gyro0.rtc\")).state(ERROR) {\n    attempt { reset() }\n    reset()\n}\n",
                )
            val run = runWatchingGyro(localisation, restart)

            gyro.breakDown()
            run.awaitLine("the handler's failure") { "failed at broken.coord.kts:3" in it }
            val result = run.stop()
            assertEquals(0, result.statusCode, result.stderr)
            val path = localisation.path("gyro0.rtc")
            assertTrue(
                "stopped by SIGINT; 1 handler failure; 2 failed actions (1 attempted, went on)\n" in result.stdout,
                result.stdout,
            )
            // The reset that stopped the handler is on line 3; its failure surfaced after the call suspended.
            assertTrue(
                "  rule 'gyro0.rtc enters ERROR' failed at broken.coord.kts:3: OperationFailedException: $path: reset failed: RTC_ERROR (in context 0; still ERROR at its 3000 ms deadline)\n" in
                    result.stdout,
                result.stdout,
            )
            assertTrue(
                "  failed action: reset $path: reset failed: RTC_ERROR (in context 0; still ERROR at its 3000 ms deadline) (attempted, went on)\n" in
                    result.stdout,
                result.stdout,
            )
            assertTrue(
                "  failed action: reset $path: reset failed: RTC_ERROR (in context 0; still ERROR at its 3000 ms deadline) (stopped its handler)\n" in
                    result.stdout,
                result.stdout,
            )
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
        assertTrue(
            "laser0 could not be reset (reset failed: RTC_ERROR (in context 0; still ERROR at its 1000 ms deadline)): it stays in ERROR" in
                result.stdout,
            result.stdout,
        )
    }

    /** Starts `rtcoord run SCRIPT` in the background and waits until the coordinator observes gyro0. */
    private fun runWatchingGyro(localisation: Localisation, script: Path): RunningCommand {
        val run = RunningCommand("-n", localisation.naming.address, "run", script.toString())
        await("the coordinator to observe gyro0", timeout = kotlin.time.Duration.parse("60s")) {
            localisation.system.component("gyro0").observerIds.isNotEmpty()
        }
        return run
    }
}
