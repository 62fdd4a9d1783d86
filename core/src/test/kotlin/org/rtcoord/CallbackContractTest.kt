package org.rtcoord

import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CosNaming.NamingContextExtHelper
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios

/** What a handler may rely on: re-entrancy, isolation, overlap policies, order, liveness. */
class CallbackContractTest {
    private val localisation = LocalisationSystem()
    private val tree = localisation.tree
    private val push = EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds)

    private fun path(name: String) = localisation.path(name)

    @AfterEach fun stop() = localisation.close()

    private suspend fun relay(name: String): ComponentNode {
        localisation.system.runtime.create(Scenarios.relay, name).activate()
        return tree.component(path("$name.rtc"))
    }

    /** Deactivates and activates [node] [times] times: 2 x [times] transitions, each awaited. */
    private suspend fun toggle(node: ComponentNode, times: Int) =
        repeat(times) {
            node.deactivate()
            node.activate()
        }

    @Test
    fun `a handler may operate on the component that triggered it`(): Unit = runBlocking {
        val laser = tree.component(path("laser0.rtc"))
        val recorder = EventRecorder()
        tree.on<StateChanged>(path("laser0.rtc"), push) { event ->
            recorder.handler(event)
            if (event.new == LifeCycle.ERROR) {
                laser.reset()
                laser.activate()
            }
        }
        localisation.system.component("laser0").fail()
        assertEquals(LifeCycle.ERROR, recorder.next<StateChanged>().new)
        assertEquals(LifeCycle.INACTIVE, recorder.next<StateChanged>().new)
        assertEquals(LifeCycle.ACTIVE, recorder.next<StateChanged>().new)
    }

    @Test
    fun `a burst of 100 transitions arrives complete and in order`(): Unit = runBlocking {
        val node = relay("burst0")
        val seen = CopyOnWriteArrayList<LifeCycle>()
        tree.on<StateChanged>(node, StateChanged::class.java, push) { seen += it.new }
        val fixture = localisation.system.component("burst0")
        val context = fixture.ref.get_owned_contexts()[0]
        repeat(50) {
            context.deactivate_component(fixture.ref)
            context.activate_component(fixture.ref)
        }
        await("100 transitions") { seen.size >= 100 }
        assertEquals(List(50) { listOf(LifeCycle.INACTIVE, LifeCycle.ACTIVE) }.flatten(), seen.toList())
    }

    @Test
    fun `queue delivers everything in order to a slow handler`(): Unit = runBlocking {
        val node = relay("queued0")
        val seen = CopyOnWriteArrayList<LifeCycle>()
        tree.on<StateChanged>(node, StateChanged::class.java, push) {
            delay(30)
            seen += it.new
        }
        toggle(node, 5)
        await("10 transitions") { seen.size >= 10 }
        assertEquals(List(5) { listOf(LifeCycle.INACTIVE, LifeCycle.ACTIVE) }.flatten(), seen.toList())
    }

    @Test
    fun `skip drops what comes while the handler runs, latest keeps only the newest`(): Unit = runBlocking {
        val node = relay("busy0")
        val skipped = CopyOnWriteArrayList<StateChanged>()
        val latest = CopyOnWriteArrayList<StateChanged>()
        tree.on<StateChanged>(node, StateChanged::class.java, EventOptions(WatchMode.PUSH, overlap = Overlap.SKIP)) {
            skipped += it
            delay(400)
        }
        tree.on<StateChanged>(node, StateChanged::class.java, EventOptions(WatchMode.PUSH, overlap = Overlap.LATEST)) {
            latest += it
            delay(400)
        }
        toggle(node, 5)
        await("the latest transition to reach the LATEST handler") {
            latest.lastOrNull()?.let { it.old == LifeCycle.INACTIVE && latest.size >= 2 } == true
        }
        assertEquals(LifeCycle.INACTIVE, skipped.first().new, "the first transition is always delivered")
        assertTrue(skipped.size < 10, "SKIP delivered ${skipped.size} of 10")
        assertTrue(latest.size < 10, "LATEST delivered ${latest.size} of 10")
        assertEquals(LifeCycle.ACTIVE, latest.last().new)
    }

    @Test
    fun `a handler that throws keeps receiving, and a slow one delays nobody`(): Unit = runBlocking {
        val node = relay("robust0")
        val afterFailure = EventRecorder()
        var first = true
        tree.on<StateChanged>(node, StateChanged::class.java, push) { event ->
            if (first) {
                first = false
                throw IllegalStateException("handler bug")
            }
            afterFailure.handler(event)
        }
        tree.on<StateChanged>(node, StateChanged::class.java, push) { delay(60_000) }
        val prompt = EventRecorder()
        tree.on<StateChanged>(node, StateChanged::class.java, push, prompt.handler)

        val started = TimeSource.Monotonic.markNow()
        node.deactivate()
        prompt.next<StateChanged>(timeout = 1.seconds)
        node.activate()
        assertEquals(LifeCycle.ACTIVE, afterFailure.next<StateChanged>().new)
        assertTrue(started.elapsedNow() < 5.seconds)
    }

    @Test
    fun `a killed component process is lost within missed beats times interval plus a second`(): Unit = runBlocking {
        FixtureProcess.start("--naming", localisation.naming.address, "--scenario", "component:victim0").use { process
            ->
            val recorder = EventRecorder()
            tree.on(
                path("victim0.rtc"),
                RtcEvent::class.java,
                EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds, missedBeats = 3),
                recorder.handler,
            )
            val killed = TimeSource.Monotonic.markNow()
            process.kill()
            recorder.next<HeartbeatLost>(timeout = 1600.milliseconds)
            val lostAfter = killed.elapsedNow()
            assertTrue(recorder.next<BecameZombie>().cause is UnreachableException)
            println("SIGKILL to HeartbeatLost: $lostAfter (limit 3 x 200 ms + 1 s)")
        }
    }

    @Test
    fun `naming and manager listings report what appears and vanishes`(): Unit = runBlocking {
        val naming = EventRecorder()
        val managed = EventRecorder()
        tree.on(localisation.host, RtcEvent::class.java, EventOptions(pollPeriod = 100.milliseconds), naming.handler)
        tree.on(
            path("manager.mgr/manager_slave"),
            ManagerComponentChanged::class.java,
            EventOptions(pollPeriod = 100.milliseconds),
            managed.handler,
        )

        val master = tree.manager(path("manager.mgr"))
        master.create("odo_localise")
        assertEquals("odo_localise0.rtc", naming.next<NodeAppeared>().child.name)
        assertEquals(
            "odo_localise0",
            managed.next<ManagerComponentChanged>().also { assertTrue(it.created) }.instanceName,
        )

        master.delete("odo_localise0")
        assertEquals(path("odo_localise0.rtc"), naming.next<NodeVanished>().child.toString())
        assertEquals(false, managed.next<ManagerComponentChanged>().created)
    }

    @Test
    fun `a component the tree creates is reported at once, not at the listing's next period`(): Unit = runBlocking {
        val naming = EventRecorder()
        tree.on(localisation.host, NodeAppeared::class.java, EventOptions(pollPeriod = 1.hours), naming.handler)
        tree.manager(path("manager.mgr")).create("odo_localise")
        assertEquals("odo_localise0.rtc", naming.next<NodeAppeared>().child.name)
    }

    @Test
    fun `a name bound again to another component that answers is noticed, though watched names are resolved less`():
        Unit = runBlocking {
        tree.on(localisation.host, NodeAppeared::class.java, EventOptions(pollPeriod = 50.milliseconds)) {}
        val context = tree.node(localisation.host) as ContextNode
        fun bound(name: String) = (context.listed.value?.firstOrNull { it.name == name } as? ComponentNode)?.component
        val odometry = bound("odometry0.rtc")!!
        val orb = localisation.system.runtime.orb.orb
        val naming = NamingContextExtHelper.narrow(orb.string_to_object(localisation.naming.corbaloc))
        naming.rebind(naming.to_name("${RuntimeProcess.hostContext}/gyro0.rtc"), odometry.ref)
        await("gyro0.rtc listed as the component bound to it now") { bound("gyro0.rtc") === odometry }
    }

    @Test
    fun `cancelling the last registration and closing the tree detach the observer`(): Unit = runBlocking {
        val gyro = localisation.system.component("gyro0")
        val first = tree.on<StateChanged>(path("gyro0.rtc"), push) {}
        val second = tree.on<StateChanged>(path("gyro0.rtc"), push) {}
        assertEquals(1, gyro.observerIds.size, "one observer, shared")
        first.cancel()
        assertEquals(1, gyro.observerIds.size)
        second.cancel()
        await("the observer to be detached on cancel") { gyro.observerIds.isEmpty() }

        tree.on<StateChanged>(path("gyro0.rtc"), push) {}
        assertTrue(gyro.observerIds.single().startsWith("rtcoord-observer-"))
        tree.close()
        assertEquals(emptySet<String>(), gyro.observerIds, "detached before close returned")
    }
}
