package org.rtcoord.cli

import RTC.RTObjectHelper
import com.github.ajalt.clikt.testing.CliktCommandTestResult
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.Socket
import kotlin.time.Duration.Companion.seconds
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CosNaming.NamingContextExtHelper
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue
import org.rtcoord.fixtures.iiopAddresses
import org.rtcoord.fixtures.listeningSockets
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios

/** `watch`: one line per event while it runs, observers gone when it stops. */
class WatchCommandTest {
    private val localisation = Localisation()
    private val gyro = localisation.path("gyro0.rtc")

    @AfterEach fun stop() = localisation.close()

    /**
     * Runs `watch ARGUMENTS` until it has printed [present] lines, then deactivates and activates gyro0 twice, each
     * change made once the one before it is printed ([changed] tells its lines); returns what the command printed by
     * then.
     */
    private fun watchWhileToggling(
        vararg arguments: String,
        present: Int,
        changed: (String) -> Boolean,
    ): CliktCommandTestResult =
        RunningCommand(*arguments).use { watching ->
            watching.awaitLines("the components' present lines", present) { it.isNotEmpty() }
            for (change in 1..4) {
                runRtcoord(if (change % 2 == 1) "deact" else "act", gyro).ok()
                watching.awaitLines("change $change of gyro0", change, line = changed)
            }
            watching.stop()
        }

    @Test
    fun `prints a timestamped line per event, after a line per component saying how it is watched`() {
        val printed =
            watchWhileToggling("watch", localisation.host, present = 4) { "gyro0.rtc state" in it }
                .ok()
                .lines()
                .filter { it.isNotEmpty() }
        val (watched, lines) = printed.partition { " watched: " in it }
        val line =
            Regex(
                """\d{4}-\d\d-\d\d \d\d:\d\d:\d\d\.\d{3} /\S+/gyro0\.rtc state in context 0: (ACTIVE -> INACTIVE|INACTIVE -> ACTIVE)"""
            )
        assertTrue(lines.all { line.matches(it) }, lines.joinToString("\n"))
        assertEquals(
            List(2) { listOf("ACTIVE -> INACTIVE", "INACTIVE -> ACTIVE") }.flatten(),
            lines.map { it.substringAfter("context 0: ") },
            lines.joinToString("\n"),
        )
        // Each component's state and how it is watched, once each, before any event.
        val how =
            Regex(
                """\S+ \S+ /\S+/(\w+)\.rtc (ACTIVE|INACTIVE), [^;]+; watched: pushed by its OpenRTM::ComponentObserver, heartbeat every 1s"""
            )
        assertEquals(
            listOf("gyro0", "laser0", "laser_localise0", "odometry0"),
            watched.map { how.matchEntire(it)?.groupValues?.get(1) }.sortedBy { it },
            watched.joinToString("\n"),
        )
        assertTrue(
            printed.indexOfLast { " watched: " in it } < printed.indexOfFirst { "gyro0.rtc state" in it },
            printed.joinToString("\n"),
        )
    }

    @Test
    fun `polls with --poll and prints JSON lines with --json`() {
        val printed =
            watchWhileToggling("--json", "watch", gyro, "--poll", "100ms", present = 1) { "\"StateChanged\"" in it }
                .ok()
                .lines()
                .filter { it.isNotEmpty() }
        val present =
            Regex(
                """\{"time":"[^"]+","path":"\Q$gyro\E","event":"Present","state":"(ACTIVE|INACTIVE)","connections":\{[^}]*},"alive":true,""" +
                    """"method":"polled","pollPeriodMillis":100,"reason":"polling was asked for"}"""
            )
        assertTrue(present.matches(printed.first()), printed.first())
        val lines = printed.drop(1)
        val line =
            Regex(
                """\{"time":"[^"]+","path":"\Q$gyro\E","event":"StateChanged","sequence":\d+,"handle":0,"old":"(ACTIVE|INACTIVE)","new":"(ACTIVE|INACTIVE)"}"""
            )
        assertEquals(4, lines.size, lines.joinToString("\n"))
        assertTrue(lines.all { line.matches(it) }, lines.joinToString("\n"))
    }

    @Test
    fun `the observers it attached are detached when --for has passed, or when it is interrupted`() {
        val started = System.nanoTime()
        runRtcoord("watch", gyro, "--for", "1s").ok()
        assertTrue((System.nanoTime() - started) / 1_000_000 >= 1_000, "stopped before --for had passed")
        assertEquals(emptySet<String>(), localisation.system.component("gyro0").observerIds)

        runRtcoordUntil("watch", gyro, what = "gyro0's present line") { "gyro0.rtc" in it }.ok()
        assertEquals(emptySet<String>(), localisation.system.component("gyro0").observerIds)
    }

    /** Where the observer `watch` attached to gyro0 is reached, and where that port is listened on, while it runs. */
    private fun observerEndpoint(vararg global: String): Pair<List<String>, List<String>> {
        val watching = RunningCommand(*global, "watch", gyro)
        val component = localisation.system.component("gyro0")
        val observer =
            awaitValue("watch to attach its observer", 30.seconds) { component.observerReferences.firstOrNull() }
        val carried = iiopAddresses(localisation.system.runtime.orb.orb, observer).map { it.substringBeforeLast(':') }
        val port = iiopAddresses(localisation.system.runtime.orb.orb, observer).first().substringAfterLast(':').toInt()
        val listening = listeningSockets().filter { it.port == port }.map { it.address.hostAddress }
        watching.stop().ok()
        return carried to listening
    }

    @Test
    fun `the observer listens on loopback alone for a local name server, or on --listen`() {
        assertEquals(listOf("127.0.0.1") to listOf("127.0.0.1"), observerEndpoint())
        assertEquals(listOf("127.0.0.2") to listOf("127.0.0.2"), observerEndpoint("--listen", "127.0.0.2"))
    }

    @Test
    fun `a slave manager that dies is one line naming the components that went with it`() {
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
                val watching = RunningCommand("watch", localisation.host)
                val hosted = remoteComponent("hosted0.rtc")
                await("watch to observe hosted0", 30.seconds) {
                    hosted.get_service_profiles().any { it.id.startsWith("rtcoord-observer-") }
                }
                process.kill()
                watching.awaitLine("the manager's death") { " manager stopped answering " in it }
                // A marker: gyro0's change is printed after anything the death still had to say.
                runRtcoord("deact", gyro).ok()
                watching.awaitLine("gyro0's deactivation") { "gyro0.rtc state" in it }
                val lines = watching.stop().ok().lines()
                val died = lines.filter { " manager stopped answering " in it }
                assertEquals(1, died.size, lines.joinToString("\n"))
                val line =
                    Regex(
                        """\S+ \S+ /\S+/manager_${process.pid} manager stopped answering \(unreachable \(\w+.*\)\); its components went with it: hosted0\.rtc"""
                    )
                assertTrue(line.matches(died.single()), died.single())
                // Pushed, or polled when the kill cut the attachment's reply short: either way said once.
                assertEquals(1, lines.count { "hosted0.rtc " in it && "watched: " in it }, lines.joinToString("\n"))
            }
    }

    /** The component bound at [name] in the host context, as a client sees it. */
    private fun remoteComponent(name: String): RTC.RTObject {
        val orb = localisation.system.runtime.orb.orb
        val naming = NamingContextExtHelper.narrow(orb.string_to_object(localisation.naming.corbaloc))
        return RTObjectHelper.narrow(naming.resolve_str("${RuntimeProcess.hostContext}/$name"))
    }

    @Test
    fun `starts with each component's state, a change made just before included`() {
        runRtcoord("deact", gyro).ok()
        val printed =
            RunningCommand("watch", localisation.host).use { watching ->
                watching.awaitLines("a line per component", 4) { " watched: " in it }
                watching.stop().ok().lines()
            }
        val states =
            printed
                .mapNotNull {
                    Regex("""\S+ \S+ /\S+/(\w+)\.rtc (\w+), .*; watched: .*""").matchEntire(it)?.destructured?.let {
                        (name, state) ->
                        name to state
                    }
                }
                .toMap()
        assertEquals(
            mapOf("gyro0" to "INACTIVE", "laser0" to "ACTIVE", "laser_localise0" to "ACTIVE", "odometry0" to "ACTIVE"),
            states,
            printed.joinToString("\n"),
        )
    }

    @Test
    fun `a component that appears is printed with what happened to it before it was found`() {
        val printed =
            RunningCommand("watch", localisation.host).use { watching ->
                watching.awaitLines("a line per component", 4) { " watched: " in it }
                localisation.system.runtime.create(Scenarios.relay, "late0").activate()
                watching.awaitLine("late0 found active") {
                    "late0.rtc" in it &&
                        (it.endsWith("appeared: ACTIVE, no connection") || it.endsWith("INACTIVE -> ACTIVE"))
                }
                watching.stop().ok().lines()
            }
        val appeared = printed.single { "late0.rtc appeared" in it }
        // Found after its activation, or between its creation and its activation, which then follows it.
        assertTrue(
            appeared.endsWith("late0.rtc appeared: ACTIVE, no connection") ||
                printed.last { "late0.rtc" in it }.endsWith("INACTIVE -> ACTIVE"),
            printed.joinToString("\n"),
        )
    }

    @Test
    fun `a name server that does not answer is said, not silently watched`() {
        // Bound and never listening: connections to it are refused for as long as the test holds it.
        Socket().use { reserved ->
            reserved.bind(InetSocketAddress(InetAddress.getLoopbackAddress(), 0))
            val server = "127.0.0.1:${reserved.localPort}"
            val printed =
                runRtcoordUntil("-n", server, "watch", "/$server/", what = "the name server said unreachable") {
                        "unreachable" in it
                    }
                    .ok()
                    .lines()
                    .filter { it.isNotEmpty() }
            assertEquals(1, printed.size, printed.joinToString("\n"))
            assertTrue(
                Regex("""\S+ \S+ /\Q$server\E name server unreachable \(.+\).*""").matches(printed.single()),
                printed.single(),
            )
        }
    }

    @Test
    fun `an FSM component's machine is a line per state it enters`() {
        val microwave = localisation.system.runtime.create(Scenarios.microwave, "Microwave0")
        val printed =
            RunningCommand("watch", localisation.path("Microwave0.rtc")).use { watching ->
                await("watch's observer attached") { microwave.observerIds.isNotEmpty() }
                microwave.fsmEvent("minute")
                microwave.fsmEvent("start")
                watching.awaitLine("the microwave cooking") { "Cooking" in it }
                watching.stop().ok()
            }
        // What it entered before every event was caught is told by its first line, what it entered after by lines of
        // their own.
        val first =
            Regex("""/Microwave0\.rtc [^;]*, FSM state (\w+|unknown \([^)]*\)); watched""")
                .find(printed)
                ?.groupValues
                ?.get(1)
        assertTrue(first != null, printed)
        val changes =
            Regex("""/Microwave0\.rtc FSM state: (\S+|\(not told\)) -> (\w+)\n""")
                .findAll(printed)
                .map { it.groupValues[1] to it.groupValues[2] }
                .toList()
        val told = listOf(first!!.takeUnless { it.startsWith("unknown") } ?: "(not told)") + changes.map { it.second }
        // Each line follows on from what was told before it: nothing lost, nothing told twice.
        assertEquals(told.zipWithNext(), changes, printed)
        assertTrue(told.takeLast(2) == listOf("Programmed", "Cooking") || told == listOf("Cooking"), printed)
    }

    @Test
    fun `durations must be positive and well formed`() {
        runRtcoord("watch", gyro, "--for", "soon").usageError()
        runRtcoord("watch", gyro, "--poll", "0s").usageError()
    }
}
