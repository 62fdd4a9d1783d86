package org.rtcoord

import OpenRTM.StatusKind
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicLong
import kotlin.concurrent.thread
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.EnumSource
import org.rtcoord.fixtures.OmniNames
import org.rtcoord.fixtures.await
import org.rtcoord.internal.events.ListingMonitor
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService
import org.rtcoord.runtime.naming.NamingSnapshot

/**
 * The tree keeps working through the faults of a running system, reports each, recovers when it ends, and loses no
 * later event: a name server restarted, a servant that hangs, observer notifications that are malformed, duplicated,
 * out of order or forged, and a coordinator restarted over its own stale observers.
 */
class FaultToleranceTest {
    private val push = EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds, pollPeriod = 100.milliseconds)

    /** A name server a test can stop and start again on the same port, with its bindings or without. */
    enum class NameServerRestart(val keepsData: Boolean) {
        EMBEDDED_EMPTY(false),
        EMBEDDED_WITH_DATA(true),
        OMNINAMES_EMPTY(false),
        OMNINAMES_WITH_DATA(true);

        fun start(): RestartableNameServer = if (name.startsWith("EMBEDDED")) Embedded(keepsData) else Omni(keepsData)
    }

    interface RestartableNameServer : AutoCloseable {
        val address: String
        val corbaloc: String

        fun stop()

        fun restart()
    }

    private class Embedded(private val keepsData: Boolean) : RestartableNameServer {
        private var service = NamingService.start()
        private var saved: NamingSnapshot? = null
        override val address = service.address
        override val corbaloc = service.corbaloc

        override fun stop() {
            saved = if (keepsData) service.snapshot() else null
            service.close()
        }

        override fun restart() {
            service = NamingService.start(service.port, saved)
        }

        override fun close() = service.close()
    }

    private class Omni(private val keepsData: Boolean) : RestartableNameServer {
        private var server = OmniNames.start()
        override val address = server.address
        override val corbaloc = server.corbaloc

        override fun stop() = server.stop()

        override fun restart() {
            server = server.restart(keepsData)
        }

        override fun close() = server.close()
    }

    @ParameterizedTest
    @EnumSource(NameServerRestart::class)
    fun `a name server restarted is read again, components registering again are found, and events flow throughout`(
        restart: NameServerRestart
    ): Unit = runBlocking {
        LogCapture(ListingMonitor::class.java).use { logs ->
            restart.start().use { server ->
                Scenarios.localisation(server.corbaloc).use { system ->
                    RtcTree(TreeConfig(listOf(server.address))).use { tree ->
                        val host = "/${server.address}/${RuntimeProcess.hostContext}"
                        val recorder = EventRecorder()
                        tree.on(host, RtcEvent::class.java, push, recorder.handler)

                        server.stop()
                        system.component("gyro0").fail()
                        assertEquals(
                            LifeCycle.ERROR,
                            recorder.next<StateChanged> { it.source.name == "gyro0.rtc" }.new,
                            "events flow while the name server is down",
                        )
                        await("the outage to be reported") {
                            logs.lines.any { it.startsWith("$host: ") && it.endsWith("listing it again every 100ms") }
                        }

                        server.restart()
                        if (!restart.keepsData) {
                            // As OpenRTM's periodic naming update does: every process registers again.
                            system.runtime.rebindAll()
                            system.master!!.runtime.bind("manager.mgr", system.master!!.ref)
                        }
                        system.runtime.create(Scenarios.relay, "late0")
                        recorder.next<NodeAppeared>(timeout = 10.seconds) { it.child.name == "late0.rtc" }
                        // Logged by the listing loop once its listing returns, while the listing's changes are
                        // announced by another coroutine: the line may follow the event.
                        await("the recovery to be reported") { "$host: listed again" in logs.lines }
                        system.component("late0").activate()
                        assertEquals(
                            LifeCycle.ACTIVE,
                            recorder.next<StateChanged> { it.source.name == "late0.rtc" }.new,
                            "a component registered after the restart is watched",
                        )
                        system.component("laser0").fail()
                        assertEquals(
                            LifeCycle.ERROR,
                            recorder.next<StateChanged> { it.source.name == "laser0.rtc" }.new,
                            "events flow after the restart",
                        )

                        tree.refresh()
                        val found =
                            tree
                                .find(RtcPath(host)) { it.path.parent == RtcPath(host) }
                                .toList()
                                .map { it.name }
                                .toSet()
                        assertEquals(
                            setOf(
                                "laser0.rtc",
                                "gyro0.rtc",
                                "odometry0.rtc",
                                "laser_localise0.rtc",
                                "late0.rtc",
                                "manager.mgr",
                            ),
                            found,
                        )
                        assertEquals(LifeCycle.ERROR, tree.component("$host/laser0.rtc").state())
                    }
                }
            }
        }
    }

    @Test
    fun `a hung servant times out alone, while other components' calls and events proceed promptly`(): Unit =
        runBlocking {
            LocalisationSystem().use { localisation ->
                val tree = localisation.tree
                val hung = localisation.system.runtime.create(Scenarios.relay, "hung0").also { it.activate() }
                val hungNode = tree.component(localisation.path("hung0.rtc"))
                val gyro = tree.component(localisation.path("gyro0.rtc"))
                val hungEvents = EventRecorder()
                val gyroEvents = EventRecorder()
                tree.on(hungNode, RtcEvent::class.java, push, hungEvents.handler)
                tree.on(gyro, RtcEvent::class.java, push, gyroEvents.handler)

                hung.hang()
                try {
                    val started = TimeSource.Monotonic.markNow()
                    val stuck = async { runCatching { hungNode.deactivate() }.exceptionOrNull() }
                    repeat(3) {
                        val before = TimeSource.Monotonic.markNow()
                        gyro.deactivate()
                        assertEquals(LifeCycle.INACTIVE, gyroEvents.next<StateChanged>(timeout = 2.seconds).new)
                        gyro.activate()
                        assertEquals(LifeCycle.ACTIVE, gyroEvents.next<StateChanged>(timeout = 2.seconds).new)
                        println(
                            "gyro0 deactivated and activated, both events received, in ${before.elapsedNow()} while hung0 hangs"
                        )
                    }
                    assertTrue(stuck.await() is TimedOutException, "only the call to the hung component times out")
                    assertTrue(started.elapsedNow() >= tree.config.callTimeout, "the hung call waited for its deadline")
                    hungEvents.next<HeartbeatLost>(timeout = 10.seconds)
                    hungEvents.next<BecameZombie>(timeout = 10.seconds)
                } finally {
                    hung.release()
                }
                hungEvents.next<Recovered>(timeout = 10.seconds)
                // The deactivation held while it hung goes through once released, as a late CORBA call does, and the
                // tree tells of it: whether its read on recovery, the observer it attaches anew or the read that
                // confirms the attachment sees it. Activating before then could hide both transitions from the tree.
                hungEvents.next<StateChanged> { it.new == LifeCycle.INACTIVE }
                assertEquals(RTC.LifeCycleState.INACTIVE_STATE, hung.state)
                hungNode.activate()
                assertEquals(
                    LifeCycle.ACTIVE,
                    hungEvents.next<StateChanged> { it.new == LifeCycle.ACTIVE }.new,
                    "events flow again once it answers",
                )
            }
        }

    @Test
    fun `malformed, duplicated, out-of-order and misaddressed notifications produce no event`(): Unit = runBlocking {
        LocalisationSystem().use { localisation ->
            ObserverClient().use { client ->
                val (node, recorder, _, observer) = observedRelay(localisation, client)

                val notifications =
                    listOf(
                        // malformed
                        StatusKind.RTC_STATUS to "",
                        StatusKind.RTC_STATUS to "ACTIVE",
                        StatusKind.RTC_STATUS to "RUNNING:0",
                        StatusKind.RTC_STATUS to "INACTIVE:x",
                        StatusKind.RTC_STATUS to "INACTIVE:0:1",
                        // duplicated: the state it is in, again and again
                        StatusKind.RTC_STATUS to "ACTIVE:0",
                        StatusKind.RTC_STATUS to "ACTIVE:0",
                        StatusKind.RTC_STATUS to "ACTIVE:0",
                        // out of order: ERROR then INACTIVE, where the component is still ACTIVE
                        StatusKind.RTC_STATUS to "ERROR:0",
                        StatusKind.RTC_STATUS to "INACTIVE:0",
                        // about contexts, ports and configuration sets the component does not have
                        StatusKind.RTC_STATUS to "INACTIVE:7",
                        StatusKind.EC_STATUS to "ATTACHED:1234",
                        StatusKind.PORT_PROFILE to "CONNECT:ghost0.out",
                        StatusKind.CONFIGURATION to "UPDATE_CONFIG_SET: nowhere",
                        StatusKind.COMPONENT_PROFILE to "ghost0",
                    )
                // The out-of-order pair leads the reads, which find ACTIVE until one decides at the end of the grace
                // period: that disagreement ending is the tree done with the notifications.
                val ended = localisation.tree.core.disagreementsEnded.get()
                notifications.forEach { (kind, hint) -> client.send(observer, kind, hint) }
                client.sync(observer)
                await("the reads to settle what the notifications hinted") {
                    localisation.tree.core.disagreementsEnded.get() > ended
                }
                assertEquals(emptyList<RtcEvent>(), recorder.drained<RtcEvent>(), "no event from notifications alone")

                node.deactivate()
                assertEquals(
                    StateChanged(node, 0, LifeCycle.ACTIVE, LifeCycle.INACTIVE),
                    recorder.next<RtcEvent>(),
                    "the next real change, and nothing before it",
                )
            }
        }
    }

    @Test
    fun `a notification to an object id the tree did not register is rejected and produces no event`(): Unit =
        runBlocking {
            LocalisationSystem().use { localisation ->
                ObserverClient().use { client ->
                    val (_, recorder, subscription, genuine) = observedRelay(localisation, client)
                    val fixture = localisation.system.component("subject0")

                    val forged = client.forged(genuine)
                    assertThrows(org.omg.CORBA.OBJECT_NOT_EXIST::class.java) {
                        client.sendExpectingReply(forged, StatusKind.RTC_STATUS, "INACTIVE:0")
                    }
                    assertTrue(forged._non_existent())
                    client.sendExpectingReply(genuine, StatusKind.HEARTBEAT, "")

                    // The observer's own id no longer works once the tree detached it.
                    subscription.cancel()
                    await("the observer to be detached and deactivated") {
                        fixture.observerIds.isEmpty() && !client.exists(genuine)
                    }
                    assertThrows(org.omg.CORBA.OBJECT_NOT_EXIST::class.java) {
                        client.sendExpectingReply(genuine, StatusKind.RTC_STATUS, "INACTIVE:0")
                    }
                    assertEquals(emptyList<RtcEvent>(), recorder.drained<RtcEvent>())
                }
            }
        }

    @Test
    fun `a hint implausible for the known state makes the tree read the component, and it converges to the real state`():
        Unit = runBlocking {
        LocalisationSystem().use { localisation ->
            ObserverClient().use { client ->
                val fixture = localisation.system.runtime.create(Scenarios.relay, "subject0").also { it.activate() }
                val node = localisation.tree.component(localisation.path("subject0.rtc"))
                val recorder = EventRecorder()
                // Heartbeats far apart: only the hints sent here may make the tree read the component.
                localisation.tree.on(
                    node,
                    RtcEvent::class.java,
                    EventOptions(WatchMode.PUSH, heartbeat = 60.seconds),
                    recorder.handler,
                )
                assertTrue(recorder.next<WatchMethodChanged>().new is WatchMethod.Pushed, "pushed")
                val profile = client.profile(fixture)
                // The component stops telling the tree anything: what changes now, only a read can find.
                client.detach(fixture, profile.id)
                val context = fixture.ref.get_owned_contexts()[0]

                context.deactivate_component(fixture.ref)
                client.send(profile.service, StatusKind.RTC_STATUS, "CREATED:0") // ACTIVE to CREATED cannot happen
                assertEquals(
                    StateChanged(node, 0, LifeCycle.ACTIVE, LifeCycle.INACTIVE),
                    recorder.next<RtcEvent>(),
                    "the real change, not the hinted one",
                )
                assertEquals(LifeCycle.INACTIVE, node.snapshots.value!!.state)

                context.activate_component(fixture.ref)
                client.send(profile.service, StatusKind.RTC_STATUS, "ERROR:5") // no context with handle 5
                assertEquals(StateChanged(node, 0, LifeCycle.INACTIVE, LifeCycle.ACTIVE), recorder.next<RtcEvent>())

                context.deactivate_component(fixture.ref)
                client.send(profile.service, StatusKind.RTC_STATUS, "DEACTIVATED") // names no state
                assertEquals(StateChanged(node, 0, LifeCycle.ACTIVE, LifeCycle.INACTIVE), recorder.next<RtcEvent>())
                context.activate_component(fixture.ref)
                client.send(profile.service, StatusKind.RTC_STATUS, "ACTIVE:0")
                assertEquals(StateChanged(node, 0, LifeCycle.INACTIVE, LifeCycle.ACTIVE), recorder.next<RtcEvent>())

                val connector = localisation.system.connect("subject0:out", "subject0:in")
                client.send(profile.service, StatusKind.PORT_PROFILE, "CONNECT:subject0.nowhere") // no such port
                val connected = listOf(recorder.next<RtcEvent>(), recorder.next<RtcEvent>()).map { it as PortConnected }
                assertEquals(setOf("out", "in"), connected.map { it.port }.toSet())
                assertTrue(connected.all { it.connector.id == connector })
                assertEquals(LifeCycle.ACTIVE, node.snapshots.value!!.state)
                assertEquals(listOf(connector), node.snapshots.value!!.port("out")!!.connectors.map { it.id })
            }
        }
    }

    @Test
    fun `a tree closes promptly while a peer floods its observer with notifications`(): Unit = runBlocking {
        LocalisationSystem().use { localisation ->
            ObserverClient().use { client ->
                val observer = observedRelay(localisation, client).observer

                // Faster than the observer's one thread takes them, so its queue fills and the reader waits.
                val sent = AtomicLong()
                val flooding = AtomicBoolean(true)
                val flooders =
                    List(4) {
                        thread(name = "flooder-$it", isDaemon = true) {
                            while (flooding.get()) runCatching {
                                client.send(observer, StatusKind.RTC_STATUS, "ACTIVE:0")
                            }
                                .onSuccess { sent.incrementAndGet() }
                        }
                    }
                try {
                    await("the flood to outrun the observer") { sent.get() > FLOOD }
                    val closing = thread(name = "closing") { localisation.tree.close() }
                    closing.join(20.seconds.inWholeMilliseconds)
                    assertFalse(closing.isAlive) {
                        "the tree did not close within 20 s; JacORB's threads:\n" + jacorbThreads()
                    }
                } finally {
                    flooding.set(false)
                    flooders.forEach { it.join(5.seconds.inWholeMilliseconds) }
                }
            }
        }
    }

    @Test
    fun `a coordinator restarted removes the observers its previous run left, and no other tree's`(): Unit =
        runBlocking {
            LocalisationSystem().use { localisation ->
                // Heartbeats far apart, so the component itself finds no observer dead while the test runs.
                val quiet = EventOptions(WatchMode.PUSH, heartbeat = 60.seconds)
                val crashed = RtcTree(TreeConfig(listOf(localisation.naming.address)))
                try {
                    crashed.on<StateChanged>(localisation.path("gyro0.rtc"), quiet) {}
                    restartAfterCrash(crashed, localisation, quiet)
                } finally {
                    runCatching { crashed.close() } // its ORB is gone already
                }
            }
        }

    private suspend fun restartAfterCrash(crashed: RtcTree, localisation: LocalisationSystem, quiet: EventOptions) {
        val gyro = localisation.system.component("gyro0")
        val path = localisation.path("gyro0.rtc")
        val left = gyro.observerIds.single()
        RtcTree(TreeConfig(listOf(localisation.naming.address))).use { other ->
            val alive = EventRecorder()
            other.on(path, StateChanged::class.java, quiet, alive.handler)
            val kept = (gyro.observerIds - left).single()

            // The first run dies without detaching: its ORB is gone, its observer stays registered.
            crashed.core.orb.orb.shutdown(false)
            crashed.core.orb.orb.destroy()
            assertEquals(setOf(left, kept), gyro.observerIds)

            RtcTree(TreeConfig(listOf(localisation.naming.address))).use { restarted ->
                val recorder = EventRecorder()
                restarted.on(path, StateChanged::class.java, quiet, recorder.handler)
                val mine = (gyro.observerIds - kept - left).single()
                assertEquals(
                    setOf(kept, mine),
                    gyro.observerIds,
                    "the stale observer is removed on attaching, the live one stays",
                )

                restarted.component(path).deactivate()
                assertEquals(LifeCycle.INACTIVE, recorder.next<StateChanged>().new)
                assertEquals(LifeCycle.INACTIVE, alive.next<StateChanged>().new, "the other tree still observes")
            }
        }
    }

    /** A relay the tree watches by push, what it records, and the observer [client] reaches it through. */
    private data class ObservedRelay(
        val node: ComponentNode,
        val recorder: EventRecorder,
        val subscription: Subscription,
        val observer: org.omg.CORBA.Object,
    )

    private suspend fun observedRelay(localisation: LocalisationSystem, client: ObserverClient): ObservedRelay {
        val fixture = localisation.system.runtime.create(Scenarios.relay, "subject0").also { it.activate() }
        val node = localisation.tree.component(localisation.path("subject0.rtc"))
        val recorder = EventRecorder()
        val subscription = localisation.tree.on(node, RtcEvent::class.java, push, recorder.handler)
        assertTrue(recorder.next<WatchMethodChanged>().new is WatchMethod.Pushed, "pushed")
        return ObservedRelay(node, recorder, subscription, client.profile(fixture).service)
    }

    /** Where every thread in JacORB's code stands, to tell which waits for which. */
    private fun jacorbThreads(): String =
        Thread.getAllStackTraces()
            .filterValues { trace -> trace.any { it.className.startsWith("org.jacorb") } }
            .entries
            .joinToString("\n\n") { (thread, trace) ->
                "${thread.name} (${thread.state})\n" + trace.take(16).joinToString("\n") { "  at $it" }
            }

    private companion object {
        /** Five times what the observer's POA queues before its reader waits (OrbRecipe's `queue_max`). */
        const val FLOOD = 5_000L
    }
}
