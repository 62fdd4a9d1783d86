package org.rtcoord.dsl

import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue
import org.rtcoord.runtime.RuntimeModule
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService
import org.rtcoord.runtime.rtSystem

/**
 * A coordinator running rules keeps working through the faults of the system it coordinates: it reports each fault,
 * recovers when the fault ends, and no later event is lost.
 */
class CoordinatorFaultTest {
    private val naming = NamingService.start()
    private val log = CopyOnWriteArrayList<String>()
    private val started = mutableListOf<AutoCloseable>()
    private val push = EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds, pollPeriod = 200.milliseconds)

    @AfterEach
    fun stop() {
        started.reversed().forEach { runCatching { it.close() } }
        naming.close()
    }

    private fun <T : AutoCloseable> T.closedAfter(): T = also { started += it }

    private fun coordinator(tree: RtcTree, declare: Coordination.() -> Unit): Coordinator =
        Coordinator(tree, Coordination(emptyList(), tree.config).apply(declare), push) { log += it }.closedAfter()

    @Test
    fun `a killed component is lost, a rule re-creates it through a manager, and the rules follow the new one`(): Unit =
        runBlocking {
            val system =
                rtSystem(naming.corbaloc) { manager(RuntimeModule("relays.so", listOf(Scenarios.relay))) }.closedAfter()
            val victim =
                FixtureProcess.start("--naming", naming.address, "--scenario", "component:victim0").closedAfter()
            val tree = RtcTree(TreeConfig(listOf(naming.address))).closedAfter()
            val errors = AtomicInteger()
            val coordinator =
                coordinator(tree) {
                    val manager = manager()
                    on(component("victim0")).lost { log("victim0 silent for ${it.silentMillis} ms") }
                    on(component("victim0")).zombie { manager.create("relay", "victim0").activate() }
                    on(component("victim0")).state(ERROR) {
                        errors.incrementAndGet()
                        reset()
                        activate()
                    }
                }
            coordinator.start()

            victim.kill()
            val replacement =
                awaitValue("victim0 re-created and active", 20.seconds) {
                    system.runtime.components.firstOrNull {
                        it.instanceName == "victim0" && it.state == RTC.LifeCycleState.ACTIVE_STATE
                    }
                }
            assertTrue(log.any { it.startsWith("rule 'victim0 is lost' fired: HeartbeatLost") }, log.toString())
            assertTrue(log.any { it.startsWith("rule 'victim0 becomes a zombie' fired: BecameZombie") }, log.toString())
            await("the rules to follow the new victim0") { log.any { it.startsWith("victim0 was re-created") } }

            replacement.fail()
            await("the rule to bring the new victim0 back from ERROR") {
                errors.get() == 1 && replacement.state == RTC.LifeCycleState.ACTIVE_STATE
            }
            assertEquals(0, coordinator.failures, log.toString())
        }

    @Test
    fun `a component created under the name of one that exited is the one the new reference reaches`(): Unit =
        runBlocking {
            rtSystem(naming.corbaloc) {
                    manager(RuntimeModule("relays.so", listOf(Scenarios.relay)))
                    component(Scenarios.relay, "source0")
                }
                .closedAfter()
            val tree = RtcTree(TreeConfig(listOf(naming.address))).closedAfter()
            val coordinator =
                coordinator(tree) {
                    after(0.seconds) {
                        val first = manager().create("relay", "relay9")
                        connect("source0.rtc:out", first.port("in"))
                        first.exit()
                        // The manager gives the name again once the first is cleaned up; its peer must be the new one.
                        val second = manager().create("relay", "relay9")
                        connect("source0.rtc:out", second.port("in"))
                        log("connected again")
                    }
                }
            coordinator.start()

            await("the second relay9 to be connected, or the handler to fail") {
                log.contains("connected again") || coordinator.failures > 0
            }
            assertEquals(0, coordinator.failures, log.toString())
            RtcTree(TreeConfig(listOf(naming.address))).use { witness ->
                val port = witness.port("${witness.componentNamed("relay9.rtc").path}:in")
                assertEquals(listOf("source0.out"), port.connections().map { it.ports.first().fullName })
            }
        }

    @Test
    fun `a manager killed while creating fails the creation clearly, and a later one goes through the restarted manager`():
        Unit = runBlocking {
        val trigger =
            rtSystem(naming.corbaloc) { component(Scenarios.relay, "trigger0") }.closedAfter().component("trigger0")
        val manager =
            FixtureProcess.start("--naming", naming.address, "--scenario", "localisation", "--create-delay", "60000")
                .closedAfter()
        val deadline = 10.seconds
        val tree = RtcTree(TreeConfig(listOf(naming.address), callTimeout = deadline)).closedAfter()
        val created = CopyOnWriteArrayList<String>()
        val coordinator =
            coordinator(tree) {
                on(component("trigger0")).state(ERROR) {
                    reset()
                    created += manager().create("odo_localise").path().toString()
                }
            }
        coordinator.start()

        trigger.activate()
        trigger.fail()
        manager.awaitOutput("creating odo_localise")
        val killed = TimeSource.Monotonic.markNow()
        manager.kill()
        await("the creation to fail") { coordinator.failures == 1 }
        val failedAfter = killed.elapsedNow()
        assertTrue(failedAfter < deadline, "failed $failedAfter after the kill, not at the $deadline deadline")
        val failure = log.single { it.contains(" failed: ") }
        assertTrue(failure.contains("manager.mgr: unreachable"), failure)

        FixtureProcess.start("--naming", naming.address, "--scenario", "localisation").closedAfter()
        trigger.activate()
        trigger.fail()
        await("a creation through the restarted manager", 20.seconds) { created.size == 1 }
        assertTrue(created.single().endsWith("odo_localise0.rtc"), created.toString())
        assertTrue(log.any { it.endsWith("(looked up again)") }, log.toString())
        assertEquals(1, coordinator.failures, log.toString())
    }

    @Test
    fun `the death of the master manager the script uses is reported at once, and its rule fires`(): Unit =
        runBlocking {
            val manager = FixtureProcess.start("--naming", naming.address, "--scenario", "localisation").closedAfter()
            val tree = RtcTree(TreeConfig(listOf(naming.address))).closedAfter()
            val died = CopyOnWriteArrayList<String>()
            val coordinator =
                coordinator(tree) {
                    val master = manager()
                    on(master).died { event -> died += "${event.source.name} with ${event.components.size} components" }
                    after(1.hours) { master.create("relay") }
                }
            coordinator.start()

            val killed = TimeSource.Monotonic.markNow()
            manager.kill()
            val line =
                awaitValue("the coordinator to report the master's death") {
                    log.firstOrNull { "/manager.mgr manager stopped answering (" in it }
                }
            println("master manager's death reported ${killed.elapsedNow()} after SIGKILL: $line")
            await("the rule on the master's death to fire") { died.isNotEmpty() }
            assertEquals(1, died.size, died.toString())
            assertTrue(died.single().startsWith("manager.mgr with "), died.toString())
            assertEquals(1, log.count { "/manager.mgr manager stopped answering (" in it }, log.toString())
            assertEquals(0, coordinator.failures, log.toString())
        }

    @Test
    fun `a rule on a name server fires when it stops answering and when it answers again`(): Unit = runBlocking {
        var server = NamingService.start()
        try {
            val tree = RtcTree(TreeConfig(listOf(server.address))).closedAfter()
            val heard = CopyOnWriteArrayList<String>()
            val coordinator =
                coordinator(tree) {
                    on(context("/${server.address}")).unreachable { event -> heard += "lost ${event.source.address}" }
                    on(context("/${server.address}")).reachable { event ->
                        heard += "back after ${event.downMillis} ms"
                    }
                }
            coordinator.start()
            val saved = server.snapshot()
            server.close()
            await("the rule on the outage to fire") { heard.isNotEmpty() }
            assertEquals("lost ${server.address}", heard.single())
            server = NamingService.start(server.port, saved)
            await("the rule on the return to fire") { heard.size == 2 }
            assertTrue(heard.last().startsWith("back after "), heard.toString())
            assertEquals(0, coordinator.failures, log.toString())
        } finally {
            server.close()
        }
    }

    @Test
    fun `handlers that throw, hang or lag behind the events delay no other rule and lose nothing`(): Unit =
        runBlocking {
            val system = Scenarios.localisation(naming.corbaloc).closedAfter()
            val busy = system.runtime.create(Scenarios.relay, "busy0").also { it.activate() }
            val tree = RtcTree(TreeConfig(listOf(naming.address))).closedAfter()
            val slow = CopyOnWriteArrayList<LifeCycle>()
            val prompt = CopyOnWriteArrayList<LifeCycle>()
            val coordinator =
                coordinator(tree) {
                    on(component("busy0")).stateChanged { error("handler bug") }
                    on(component("busy0")).stateChanged { awaitCancellation() }
                    on(component("busy0")).stateChanged { event ->
                        delay(50)
                        slow += event.new
                    }
                    on(component("gyro0")).stateChanged { prompt += it.new }
                }
            coordinator.start()

            val context = busy.ref.get_owned_contexts()[0]
            repeat(20) {
                context.deactivate_component(busy.ref)
                context.activate_component(busy.ref)
            }
            val gyro = system.component("gyro0")
            val before = TimeSource.Monotonic.markNow()
            gyro.ref.get_owned_contexts()[0].deactivate_component(gyro.ref)
            await("gyro0's event") { prompt == listOf(LifeCycle.INACTIVE) }
            val latency = before.elapsedNow()
            println("gyro0's event arrived ${latency} after its change, while busy0's handlers throw, hang and lag")
            assertTrue(latency < 2.seconds, "gyro0's event took $latency")

            await("every transition to reach the slow handler", 20.seconds) { slow.size == 40 }
            assertEquals(List(20) { listOf(LifeCycle.INACTIVE, LifeCycle.ACTIVE) }.flatten(), slow.toList())
            await("every failure to be counted") { coordinator.failures == 40 }
            assertTrue(
                log.any { it == "rule 'busy0 changes state' failed: IllegalStateException: handler bug" },
                log.toString(),
            )
        }
}
