package org.rtcoord

import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.nanoseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.DeadPort
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.iiopAddresses
import org.rtcoord.runtime.ObserverFlavour as FixtureFlavour
import org.rtcoord.runtime.Scenarios

/**
 * What the tree says about its own watching, over IIOP: how each component is watched (which observer, or polled and
 * why), once, and again when that changes; and a manager that dies, once, with the components that went with it.
 */
class WatchReportTest {
    private val localisation = LocalisationSystem()
    private val tree = localisation.tree

    @AfterEach fun stop() = localisation.close()

    private suspend fun relay(name: String, vararg flavours: FixtureFlavour): ComponentNode {
        localisation.system.runtime.create(Scenarios.relay.acceptingObservers(*flavours), name)
        return tree.component(localisation.path("$name.rtc"))
    }

    @Test
    fun `each component is said to be pushed by the observer flavour it took, or polled and why, once`(): Unit =
        runBlocking {
            val openRtm = relay("legacy0", FixtureFlavour.OPENRTM)
            val omg = relay("fsm0", FixtureFlavour.OMG)
            val mute = relay("mute0")
            val reported = EventRecorder()
            tree.onWatching(reported.handler)
            val auto = EventOptions(pollPeriod = 200.milliseconds, heartbeat = 500.milliseconds)
            val told =
                listOf(openRtm, omg, mute).associateWith { node ->
                    EventRecorder().also { tree.on(node, RtcEvent::class.java, auto, it.handler) }
                }

            assertEquals(
                WatchMethodChanged(openRtm, null, WatchMethod.Pushed(ObserverFlavour.OPENRTM, 500.milliseconds, null)),
                told.getValue(openRtm).next<WatchMethodChanged>(),
            )
            assertEquals(
                WatchMethodChanged(omg, null, WatchMethod.Pushed(ObserverFlavour.OMG, 500.milliseconds, null)),
                told.getValue(omg).next<WatchMethodChanged>(),
            )
            val polled =
                WatchMethod.Polled(
                    200.milliseconds,
                    "it offers no ComponentObserver (sdo.service.consumer.available_services: none)",
                )
            assertEquals(WatchMethodChanged(mute, null, polled), told.getValue(mute).next<WatchMethodChanged>())
            assertEquals(1, localisation.system.component("legacy0").observerIds.size)
            assertEquals(1, localisation.system.component("fsm0").observerIds.size)

            // A second registration on a component changes nothing and hears how it is watched, once.
            val late = EventRecorder()
            tree.on(mute, WatchMethodChanged::class.java, auto, late.handler)
            assertEquals(WatchMethodChanged(mute, null, polled), late.next<WatchMethodChanged>())

            // Polling asked for on a pushed component: still pushed, and polled too, said to every registration.
            tree.on(omg, RtcEvent::class.java, EventOptions(WatchMode.POLL, pollPeriod = 100.milliseconds)) {}
            val both = WatchMethod.Pushed(ObserverFlavour.OMG, 500.milliseconds, 100.milliseconds)
            assertEquals(
                WatchMethodChanged(omg, WatchMethod.Pushed(ObserverFlavour.OMG, 500.milliseconds, null), both),
                told.getValue(omg).next<WatchMethodChanged>(),
            )

            // Nothing more while the pushed ones beat and the polled ones are read several times: then a poll asked
            // for on each is a change every stream is told, a marker nothing else may precede.
            val (legacy, fsm, muted) = listOf("legacy0", "fsm0", "mute0").map { localisation.system.component(it) }
            val beats = legacy.heartbeats to fsm.heartbeats
            val reads = fsm.calls(PROFILE) to muted.calls(PROFILE)
            await("two heartbeats of each pushed component and five reads of each polled one") {
                legacy.heartbeats >= beats.first + 2 &&
                    fsm.heartbeats >= beats.second + 2 &&
                    fsm.calls(PROFILE) >= reads.first + 5 &&
                    muted.calls(PROFILE) >= reads.second + 5
            }
            listOf(openRtm, omg, mute).forEach { tree.on(it, StateChanged::class.java, marker) {} }
            val reports = reported.until { seen -> seen.count(::isMarker) == 3 }.filterIsInstance<WatchMethodChanged>()
            assertEquals(
                listOf(openRtm, omg, mute, omg, openRtm, omg, mute).map { it.name },
                reports.map { it.source.name },
                "once per component and change, then the markers: $reports",
            )
            assertEquals(both, reports[3].new)
            assertTrue(reports.drop(4).all(::isMarker), "$reports")
            for ((node, recorder) in told.toList() + (mute to late)) {
                val heard = recorder.until { seen -> seen.any(::isMarker) }.filterIsInstance<WatchMethodChanged>()
                assertEquals(1, heard.size, "${node.name} heard only the marker: $heard")
            }
        }

    @Test
    fun `push alone on a component that takes no observer watches nothing, and says so`(): Unit = runBlocking {
        val mute = relay("mute0")
        val told = EventRecorder()
        tree.on(mute, RtcEvent::class.java, EventOptions(WatchMode.PUSH), told.handler)
        val method = told.next<WatchMethodChanged>().new
        assertTrue(method is WatchMethod.Unwatched && "offers no ComponentObserver" in method.reason, "$method")
    }

    @Test
    fun `a slave manager killed with its components is one manager death naming them, after which each goes silent`():
        Unit = runBlocking {
        val master = localisation.system.master!!.runtime.orb.corbaloc("manager")
        FixtureProcess.start("--naming", localisation.naming.address, "--scenario", "scale:2", "--master", master)
            .use { process ->
                val events = EventRecorder()
                val reported = EventRecorder()
                tree.onWatching(reported.handler)
                tree.on(
                    localisation.host,
                    RtcEvent::class.java,
                    EventOptions(heartbeat = 200.milliseconds),
                    events.handler,
                )
                val relays = setOf("relay0.rtc", "relay1.rtc")
                val watched = List(2) { events.next<WatchMethodChanged> { it.source.name in relays }.source }
                assertEquals(relays, watched.map { it.name }.toSet())
                // Where the process listened: its manager and its components, one ORB.
                val where =
                    iiopAddresses(localisation.system.runtime.orb.orb, watched.first().component.ref)
                        .distinct()
                        .single()

                process.kill()
                val seen = events.until { seen ->
                    seen.any { it is ManagerDied } &&
                        seen.filterIsInstance<BecameZombie>().map { it.source.name }.containsAll(relays)
                }
                val died = seen.filterIsInstance<ManagerDied>().single()
                assertEquals("manager_${process.pid}", died.source.name)
                assertEquals(relays, died.components.map { it.name }.toSet())
                assertTrue(died.cause is UnreachableException, "${died.cause}")
                assertTrue(
                    died in tree.snapshot().managerOutages,
                    "the model holds the death for views that start later",
                )

                // Several probes of the dead manager and of its components, counted where the process listened; then
                // a poll asked for on gyro0 is a change both streams are told, a marker nothing else may precede.
                DeadPort(where, localisation.system.runtime.orb.orb).use { port ->
                    await("probes of the dead manager and its components", 30.seconds) {
                        port.requests("get_profile") >= PROBES && port.requests(PROFILE) >= PROBES
                    }
                    // A dead component is probed once a beat (200 ms), not at each of the watchdog's ten checks a beat:
                    // ten more probes of the two relays take four beats; at the checks' pace, a quarter of that.
                    val from = port.requests(PROFILE)
                    val since = System.nanoTime()
                    await("ten more probes of the dead relays", 30.seconds) { port.requests(PROFILE) >= from + 10 }
                    val took = (System.nanoTime() - since).nanoseconds
                    assertTrue(took >= 400.milliseconds, "ten probes of two dead relays at 200 ms heartbeats in $took")
                }
                tree.on(localisation.path("gyro0.rtc"), StateChanged::class.java, marker) {}
                assertEquals(
                    emptyList<ManagerDied>(),
                    events.until { seen -> seen.any(::isMarker) }.filterIsInstance<ManagerDied>(),
                    "one death only",
                )
                assertEquals(
                    listOf(died),
                    reported.until { seen -> seen.any(::isMarker) }.filterIsInstance<ManagerDied>(),
                    "one death only for the tree's reporters too",
                )
            }
    }

    @Test
    fun `a slave killed before its own listing was read is still one death naming what its master placed in it`():
        Unit = runBlocking {
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
                // The master's listing alone: it names the slave and what the slave runs; the slave is never listed.
                tree.manager("${localisation.host}/manager.mgr").children()
                val events = EventRecorder()
                tree.on(
                    "${localisation.host}/hosted0.rtc",
                    RtcEvent::class.java,
                    EventOptions(heartbeat = 200.milliseconds),
                    events.handler,
                )
                events.next<WatchMethodChanged>()

                process.kill()
                val died = events.next<ManagerDied>(10.seconds)
                assertEquals("manager_${process.pid}", died.source.name)
                assertEquals(listOf("hosted0.rtc"), died.components.map { it.name })
            }
    }

    @Test
    fun `a manager that stops answering and answers again is one death and one return`(): Unit = runBlocking {
        val master = localisation.system.master!!.runtime.orb.corbaloc("manager")
        RtcTree(TreeConfig(listOf(localisation.naming.address), callTimeout = 1.seconds)).use { tree ->
            FixtureProcess.start(
                    "--naming",
                    localisation.naming.address,
                    "--scenario",
                    "component:hung0",
                    "--master",
                    master,
                )
                .use { process ->
                    val events = EventRecorder()
                    tree.on(
                        localisation.host,
                        RtcEvent::class.java,
                        EventOptions(heartbeat = 300.milliseconds),
                        events.handler,
                    )
                    events.next<WatchMethodChanged> { it.source.name == "hung0.rtc" }

                    signal("STOP", process.pid)
                    try {
                        val died = events.next<ManagerDied>(15.seconds)
                        assertEquals("manager_${process.pid}", died.source.name)
                        assertEquals(listOf("hung0.rtc"), died.components.map { it.name })
                        assertTrue(died.cause is TimedOutException, "${died.cause}")
                    } finally {
                        signal("CONT", process.pid)
                    }
                    val seen = events.until { seen ->
                        seen.any { it is ManagerReturned } &&
                            seen.any { it is Recovered && it.source.name == "hung0.rtc" }
                    }
                    assertEquals(
                        listOf("manager_${process.pid}"),
                        seen.filterIsInstance<ManagerReturned>().map { it.source.name },
                    )
                    assertEquals(
                        emptyList<ManagerDied>(),
                        seen.filterIsInstance<ManagerDied>() + events.drained<ManagerDied>(),
                    )
                    assertTrue(
                        tree.snapshot().managerOutages.none { it.source.name == "manager_${process.pid}" },
                        "returned: no longer dead in the model",
                    )
                }
        }
    }

    /** A change to the marker's poll, asked for once a test has shown what it had to. */
    private fun isMarker(event: RtcEvent): Boolean =
        event is WatchMethodChanged &&
            when (val method = event.new) {
                is WatchMethod.Pushed -> method.pollPeriod == MARKER_PERIOD
                is WatchMethod.Polled -> method.period == MARKER_PERIOD
                is WatchMethod.Unwatched -> false
            }

    /** The events from now until [done] holds for them, within 15 s. */
    private fun EventRecorder.until(done: (List<RtcEvent>) -> Boolean): List<RtcEvent> {
        val seen = mutableListOf<RtcEvent>()
        val deadline = System.nanoTime() + 15.seconds.inWholeNanoseconds
        while (!done(seen)) {
            seen +=
                events.poll(deadline - System.nanoTime(), java.util.concurrent.TimeUnit.NANOSECONDS)
                    ?: throw AssertionError("not within 15 s; saw $seen")
        }
        return seen
    }

    private fun signal(name: String, pid: Long) {
        val kill = ProcessBuilder("kill", "-$name", pid.toString()).inheritIO().start()
        assertEquals(0, kill.waitFor(), "kill -$name $pid")
    }

    private companion object {
        /** What a component is read with when it is polled (the fixture counts the calls made to it). */
        const val PROFILE = "get_component_profile"

        /** The probes of a dead manager, and the reads of its components, a test lets pass to show they say nothing. */
        const val PROBES = 3

        /** The poll period asked for by a marker registration: no registration of the tests asks for it otherwise. */
        val MARKER_PERIOD = 50.milliseconds

        /** A registration that asks for the marker's poll. */
        val marker = EventOptions(WatchMode.POLL, pollPeriod = MARKER_PERIOD)
    }
}
