package org.rtcoord.dsl

import RTC.LifeCycleState
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertSame
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.EnumSource
import org.rtcoord.ComponentNode
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.RtcPath
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.rtSystem

/**
 * Supervisors against the fixtures: sensors in this JVM, hosted by a slave of the master `manager.mgr`; for the tests
 * that kill a component, a laser localiser in a separate process whose own slave joined that master, fed by the laser
 * and the odometry, so that SIGKILL takes the component and its manager down together, as it would a robot's process.
 */
class SupervisionTest :
    CoordinatedSystem(
        { naming ->
            rtSystem(naming) {
                manager(*Scenarios.localisationModules.toTypedArray())
                component(Scenarios.laser)
                component(Scenarios.odometry)
                component(Scenarios.gyro)
                component(Scenarios.odoLocalise)
                activate("laser0", "odometry0", "gyro0")
            }
        },
        EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds),
    ) {
    override fun onLogLine(line: String) {
        super.onLogLine(line)
        println("coordinator: $line")
    }

    private fun active(name: String): RuntimeComponent? =
        system.runtime.components.firstOrNull {
            it.instanceName == name && !it.isExited && it.state == LifeCycleState.ACTIVE_STATE
        }

    /** The supervisor's `stop` and `start` steps, as `stop odometry0.rtc`. */
    private fun steps(): List<String> = log.mapNotNull { line ->
        STEP.find(line)?.let { "${it.groupValues[1]} ${it.groupValues[2]}" }
    }

    /** The component [name] as a second tree reads it now, its naming context read again. */
    private suspend fun fresh(name: String): ComponentNode {
        witness.refresh(RtcPath(host), depth = 0)
        return witness.component(path(name)).also { it.refresh() }
    }

    /** The connections of port [port], each as the paths of its ports. */
    private suspend fun ends(port: String): List<List<String>> =
        witness.port(path(port)).connections().map { c -> c.ports.map { it.path.toString() } }

    private fun logged(text: String): Boolean = log.any { text in it }

    /**
     * laser_localise0 in its own process, joined to the master, fed by laser0 and odometry0, active in set precise with
     * gain 0.7.
     */
    private fun localiserProcess(): FixtureProcess {
        val process =
            FixtureProcess.start(
                "--naming",
                naming.address,
                "--scenario",
                "component:laser_localise0",
                "--type",
                "laser_localise",
                "--master",
                system.master!!.runtime.orb.corbaloc("manager"),
            )
        try {
            runBlocking {
                witness.connect(path("laser0.rtc:laser"), path("laser_localise0.rtc:laser"))
                witness.connect(path("odometry0.rtc:odo"), path("laser_localise0.rtc:odo"))
                val localiser = witness.component(path("laser_localise0.rtc"))
                localiser.setParameter("gain", "0.7", set = "precise")
                localiser.activateConfigurationSet("precise")
                localiser.activate()
            }
        } catch (e: Exception) {
            process.close()
            throw e
        }
        return process
    }

    @ParameterizedTest
    @EnumSource(Strategy::class)
    fun `a SIGKILLed component is re-created through its manager, reconnected and reconfigured, its siblings handled as the strategy says`(
        strategy: Strategy
    ): Unit = runBlocking {
        localiserProcess().use { process ->
            val ruleSaw = CopyOnWriteArrayList<String>()
            coordinator {
                supervise(component("laser0"), component("laser_localise0"), component("odometry0")) {
                    this.strategy = strategy
                    maxRestarts = 5 within 60.seconds
                }
                on(component("laser_localise0")).state(ERROR) { event -> ruleSaw += event.source.path.toString() }
            }
                .use { coordinator ->
                    coordinator.start()
                    assertEquals(
                        3,
                        coordinator.treeSubscriptions,
                        "one subscription per component: the rule on laser_localise0 shares the supervisor's",
                    )
                    // Changes after the start: a connection to odo_localise0 (not supervised) is made, the odometry's
                    // is removed.
                    witness.connect(path("laser_localise0.rtc:pose"), path("odo_localise0.rtc:odo"))
                    val odometry = witness.port(path("odometry0.rtc:odo"))
                    odometry.disconnect(odometry.connections().single().id)
                    await("the supervisor to record both changes") {
                        logged(
                            "recorded connection ${path("laser_localise0.rtc:pose")} -> ${path("odo_localise0.rtc:odo")}"
                        ) &&
                            logged(
                                "connection ${path("odometry0.rtc:odo")} -> ${path("laser_localise0.rtc:odo")} was removed"
                            )
                    }
                    val killed = TimeSource.Monotonic.markNow()
                    process.kill()

                    val localiser =
                        awaitValue("laser_localise0 to be re-created here and active", 30.seconds) {
                            active("laser_localise0")
                        }
                    println("$strategy: laser_localise0 re-created and active ${killed.elapsedNow()} after SIGKILL")
                    await("the supervisor to finish its restart") {
                        (strategy == Strategy.ONE_FOR_ONE || logged("activate ${path("odometry0.rtc")}")) &&
                            listOf("laser0", "odometry0").all {
                                system.component(it).state == LifeCycleState.ACTIVE_STATE
                            }
                    }
                    val expected =
                        when (strategy) {
                            Strategy.ONE_FOR_ONE -> listOf("start laser_localise0.rtc")
                            Strategy.ONE_FOR_ALL ->
                                listOf(
                                    "stop odometry0.rtc",
                                    "stop laser0.rtc",
                                    "start laser0.rtc",
                                    "start laser_localise0.rtc",
                                    "start odometry0.rtc",
                                )
                            Strategy.REST_FOR_ONE ->
                                listOf("stop odometry0.rtc", "start laser_localise0.rtc", "start odometry0.rtc")
                        }
                    assertEquals(expected, steps(), log.joinToString("\n"))
                    assertTrue(
                        log.any { it.endsWith("through ${path("manager.mgr")}") },
                        "re-created through the master once its own slave was gone",
                    )

                    assertEquals("precise", localiser.activeConfigurationSet)
                    assertEquals("0.7", localiser.parameter("gain"))
                    await("data from the laser to reach the new localiser") { localiser.latest("laser") != null }
                    val new = fresh("laser_localise0.rtc").snapshot()
                    assertEquals(
                        mapOf("laser" to 1, "odo" to 0, "pose" to 1),
                        new.ports.associate { it.name to it.connectors.size },
                    )
                    assertEquals(
                        listOf(listOf(path("laser0.rtc:laser"), path("laser_localise0.rtc:laser"))),
                        ends("laser0.rtc:laser"),
                        "no stale connector",
                    )
                    assertEquals(
                        listOf(listOf(path("laser_localise0.rtc:pose"), path("odo_localise0.rtc:odo"))),
                        ends("odo_localise0.rtc:odo"),
                        "no stale connector",
                    )
                    assertEquals(
                        emptyList<List<String>>(),
                        ends("odometry0.rtc:odo"),
                        "the connection removed on purpose stays removed",
                    )
                    assertEquals(null, localiser.latest("odo"))
                    val fed = system.component("odo_localise0")
                    val before = fed.latest("odo")
                    await("the new localiser's pose to reach odo_localise0") { fed.latest("odo") !== before }

                    assertEquals(
                        1,
                        localiser.observerIds.size,
                        "rules and supervisor share one observer on the new component",
                    )
                    localiser.fail()
                    await("the rule to see the new component fail") { ruleSaw.isNotEmpty() }
                    await("the supervisor to reset and reactivate the new component") {
                        logged("reset ${path("laser_localise0.rtc")}") && localiser.state == LifeCycleState.ACTIVE_STATE
                    }
                    assertSame(localiser, active("laser_localise0"), "reset, not re-created")
                    assertEquals(listOf(path("laser_localise0.rtc")), ruleSaw.toList())
                    assertEquals(3, coordinator.treeSubscriptions, "still one per component, on the re-created one")
                    assertEquals(0, coordinator.failures)
                    coordinator.close()
                    await("the observer on the new component to be detached") { localiser.observerIds.isEmpty() }
                }
        }
    }

    @Test
    fun `a component in ERROR is reset and activated again, the same component`(): Unit = runBlocking {
        val gyro = system.component("gyro0")
        coordinator { supervise(component("gyro0"), component("laser0")) { strategy = restForOne } }
            .use { coordinator ->
                coordinator.start()
                gyro.fail()
                await("gyro0, then laser0, to be active again") {
                    logged("activate ${path("laser0.rtc")}") &&
                        listOf(gyro, system.component("laser0")).all { it.state == LifeCycleState.ACTIVE_STATE }
                }
                assertSame(gyro, active("gyro0"))
                assertEquals(listOf("stop laser0.rtc", "start gyro0.rtc", "start laser0.rtc"), steps())
                assertTrue(logged("reset ${path("gyro0.rtc")}"))
                assertTrue(log.none { "re-create" in it }, log.joinToString("\n"))
            }
    }

    @Test
    fun `a component re-created by someone else during a back-off is followed, and when it fails it is restarted once and nothing healthy is stopped`():
        Unit = runBlocking {
        val laser = system.component("laser0")
        val escalations = CopyOnWriteArrayList<Escalation>()
        coordinator {
            supervise(component("laser0"), component("odometry0")) {
                backoff = exponential(2.seconds, max = 2.seconds)
                // As the supervision example's does, giving up stops what the laser feeds.
                onEscalation { escalation -> component("odometry0").deactivate().also { escalations += escalation } }
            }
        }
            .use { coordinator ->
                coordinator.start()
                witness.component(path("laser0.rtc")).exit()
                await("the supervisor to wait before re-creating laser0") {
                    logged("restarting ${path("laser0.rtc")} in 2s")
                }
                // Another client re-creates it through the master, as `rtmgr -c` would, and activates it.
                witness.manager(path("manager.mgr")).create("laser", "laser0").activate()
                val recreated =
                    awaitValue("laser0 to be re-created by the other client") {
                        active("laser0")?.takeIf { it !== laser }
                    }
                await("the supervisor to follow it instead of re-creating it") {
                    logged("${path("laser0.rtc")} was re-created by someone else: following it")
                }

                recreated.fail()
                await("the supervisor to reset and reactivate the new laser0") {
                    logged("reset ${path("laser0.rtc")}") && recreated.state == LifeCycleState.ACTIVE_STATE
                }
                assertSame(recreated, active("laser0"), "reset, not re-created")
                assertEquals(listOf("start laser0.rtc"), steps(), log.joinToString("\n"))
                assertTrue(log.none { "exists already" in it || "re-create laser0" in it }, log.joinToString("\n"))
                assertEquals(emptyList<Escalation>(), escalations.toList())
                assertEquals(
                    LifeCycleState.ACTIVE_STATE,
                    system.component("odometry0").state,
                    "the healthy odometry0 was never stopped",
                )
                assertEquals(1, recreated.observerIds.size, "the supervisor watches the new laser0 on one observer")
                assertEquals(0, coordinator.failures)
            }
    }

    @Test
    fun `beyond the restart intensity the supervisor escalates, the script handles it, and nothing is restarted any more`():
        Unit = runBlocking {
        val gyro = system.component("gyro0")
        val escalations = CopyOnWriteArrayList<Escalation>()
        coordinator {
            supervise(component("gyro0")) {
                maxRestarts = 2 within 60.seconds
                backoff = exponential(100.milliseconds, max = 1.seconds)
                onEscalation { escalation ->
                    escalations += escalation
                    component("odometry0").deactivate()
                }
            }
        }
            .use { coordinator ->
                coordinator.start()
                repeat(2) { restart ->
                    gyro.fail()
                    // Until the restart is over: a fault while the supervisor still waits for the activation is a
                    // failed restart.
                    await("restart ${restart + 1}") {
                        coordinator.supervision.single().status.value.restarts == restart + 1 &&
                            gyro.state == LifeCycleState.ACTIVE_STATE
                    }
                }
                assertTrue(
                    logged("restarting ${path("gyro0.rtc")} in 100ms (consecutive restart 1)"),
                    log.joinToString("\n"),
                )
                assertTrue(
                    logged("restarting ${path("gyro0.rtc")} in 200ms (consecutive restart 2)"),
                    log.joinToString("\n"),
                )

                gyro.fail()
                val escalation = awaitValue("the escalation") { escalations.firstOrNull() }
                assertEquals(path("gyro0.rtc"), escalation.component)
                assertEquals(2, escalation.restarts)
                assertEquals("${path("gyro0.rtc")} entered ERROR after 2 restarts within 1m", escalation.reason)
                await("the escalation handler to deactivate odometry0") {
                    system.component("odometry0").state == LifeCycleState.INACTIVE_STATE
                }
                await("the supervisor to stop watching gyro0") { gyro.observerIds.isEmpty() }
                // Stopped, it has nothing left to run: whatever happens to gyro0 now, nothing of it restarts it.
                await("the supervisor's coroutine to end") { coordinator.supervisors.single().quiet }

                witness.component(path("gyro0.rtc")).reset()
                witness.component(path("gyro0.rtc")).activate()
                gyro.fail()
                await("gyro0 to fail once more") { gyro.state == LifeCycleState.ERROR_STATE }
                assertTrue(coordinator.supervisors.single().quiet)
                assertEquals(LifeCycleState.ERROR_STATE, gyro.state, "no restart after the escalation")
                assertEquals(2, log.count { "activate ${path("gyro0.rtc")}" in it })
                assertEquals(1, escalations.size)
                assertEquals(0, coordinator.failures)
            }
    }

    @Test
    fun `permanent components are re-created after they exit, transient ones only after failures, temporary ones never`():
        Unit = runBlocking {
        val (gyro, odometry, laser) = listOf("gyro0", "odometry0", "laser0").map(system::component)
        coordinator {
            supervise(component("gyro0"), component("odometry0"), component("laser0")) {
                child("odometry0", restart = transient)
                child("laser0", restart = temporary)
            }
        }
            .use { coordinator ->
                coordinator.start()
                val restarts = { coordinator.supervision.single().status.value.restarts }
                witness.component(path("gyro0.rtc")).exit()
                val recreated = awaitValue("gyro0 to be re-created") { active("gyro0")?.takeIf { it !== gyro } }
                assertTrue(gyro.isExited)
                assertTrue(
                    logged("re-create gyro0 (gyro) through ${path("manager.mgr/manager_slave")}"),
                    log.joinToString("\n"),
                )
                await("gyro0's restart to be over") { restarts() == 1 }

                odometry.fail()
                // Until the restart is over: an exit while the supervisor still confirms the activation is a failed
                // restart.
                await("odometry0 to be reset and active again") {
                    restarts() == 2 &&
                        logged("reset ${path("odometry0.rtc")}") &&
                        odometry.state == LifeCycleState.ACTIVE_STATE
                }
                witness.component(path("odometry0.rtc")).exit()
                await("the supervisor to let odometry0 go") {
                    logged("${path("odometry0.rtc")}: it is transient and exited by itself: not restarted")
                }

                laser.fail()
                await("the supervisor to let laser0 go") {
                    logged("${path("laser0.rtc")}: it is temporary: not restarted")
                }
                // Every failure it was told of is answered: nothing it decided is still to come.
                await("the supervisor to answer every failure") { coordinator.supervisors.single().quiet }
                assertEquals(LifeCycleState.ERROR_STATE, laser.state)
                assertTrue(
                    system.runtime.components.none { it.instanceName == "odometry0" },
                    "odometry0 not re-created",
                )
                assertEquals(listOf(recreated), system.runtime.components.filter { it.instanceName == "gyro0" })
                await("the supervisor to stop watching laser0") { laser.observerIds.isEmpty() }
            }
    }

    @Test
    fun `a recovery step that fails is logged with its object and retried until the supervisor escalates, and the coordinator keeps running`():
        Unit = runBlocking {
        RuntimeProcess.start(naming.corbaloc).use { unmanaged ->
            unmanaged.create(Scenarios.relay, "orphan0").activate()
            val escalated = CopyOnWriteArrayList<String>()
            val reactions = AtomicInteger()
            coordinator {
                supervise(component("orphan0")) {
                    maxRestarts = 2 within 60.seconds
                    onEscalation { escalated += it.component }
                }
                on(component("gyro0")).state(ERROR) { reactions.incrementAndGet() }
            }
                .use { coordinator ->
                    coordinator.start()
                    assertTrue(
                        logged("no manager hosts ${path("orphan0.rtc")}: it can be reset, not re-created"),
                        log.joinToString("\n"),
                    )
                    witness.component(path("orphan0.rtc")).exit()
                    await("the supervisor to give up on orphan0") { escalated.isNotEmpty() }
                    assertEquals(
                        2,
                        log.count {
                            "re-create ${path("orphan0.rtc")} failed: no manager hosted it when it was first seen" in it
                        },
                        log.joinToString("\n"),
                    )
                    assertTrue(logged("${path("orphan0.rtc")} could not be restarted"))

                    system.component("gyro0").fail()
                    await("the coordinator to react to gyro0") { reactions.get() == 1 }
                    assertEquals(0, coordinator.failures)
                }
        }
    }

    @Test
    fun `components lost together in one killed process are one restart, restarted together`(): Unit = runBlocking {
        val process =
            FixtureProcess.start(
                "--naming",
                naming.address,
                "--scenario",
                "components:laser1=laser,localise1=laser_localise,odometry1=odometry",
                "--master",
                system.master!!.runtime.orb.corbaloc("manager"),
            )
        process.use {
            witness.connect(path("laser1.rtc:laser"), path("localise1.rtc:laser"))
            witness.connect(path("odometry1.rtc:odo"), path("localise1.rtc:odo"))
            listOf("laser1", "localise1", "odometry1").forEach { witness.component(path("$it.rtc")).activate() }
            val escalations = CopyOnWriteArrayList<Escalation>()
            coordinator {
                supervise(component("laser1"), component("localise1"), component("odometry1")) {
                    strategy = restForOne
                    // Counted per component, the three losses would escalate at the second.
                    maxRestarts = 1 within 60.seconds
                    onEscalation { escalations += it }
                }
            }
                .use { coordinator ->
                    coordinator.start()
                    val killed = TimeSource.Monotonic.markNow()
                    process.kill()
                    val back =
                        listOf("laser1", "localise1", "odometry1").map { name ->
                            awaitValue("$name to be re-created here and active", 30.seconds) { active(name) }
                        }
                    println(
                        "slave process SIGKILL to the pipeline (laser1, localise1, odometry1) ACTIVE again: ${killed.elapsedNow()}"
                    )
                    await("the localiser to get laser data again") {
                        back[1].latest("laser") != null && back[1].latest("odo") != null
                    }
                    assertEquals(emptyList<Escalation>(), escalations.toList(), log.joinToString("\n"))
                    assertEquals(1, log.count { it.endsWith("failed together: one restart") }, log.joinToString("\n"))
                    assertEquals(listOf("start laser1.rtc", "start localise1.rtc", "start odometry1.rtc"), steps())
                    assertEquals(0, coordinator.failures)
                }
        }
    }

    @Test
    fun `rest-for-one leaves the later components stopped while an earlier one cannot be restarted, and starts them once it is`():
        Unit = runBlocking {
        val (laser, odometry) = listOf("laser0", "odometry0").map(system::component)
        coordinator {
            supervise(component("laser0"), component("odometry0")) {
                strategy = restForOne
                maxRestarts = 20 within 60.seconds
                backoff = exponential(200.milliseconds, max = 200.milliseconds)
            }
        }
            .use { coordinator ->
                coordinator.start()
                laser.breakDown()
                await("laser0's reset to be refused twice") {
                    log.count { it.endsWith("odometry0.rtc stay stopped until ${path("laser0.rtc")} starts") } >= 2
                }
                assertEquals(LifeCycleState.INACTIVE_STATE, odometry.state, "the dependant stays stopped")
                assertTrue(log.none { it.endsWith("start ${path("odometry0.rtc")}") }, log.joinToString("\n"))

                laser.repair()
                await("laser0, then odometry0, to be active again") {
                    listOf(laser, odometry).all { it.state == LifeCycleState.ACTIVE_STATE }
                }
                val started = steps().filter { it.startsWith("start") }
                assertEquals("start odometry0.rtc", started.last(), started.toString())
                assertEquals(1, started.count { it == "start odometry0.rtc" }, started.toString())
                assertEquals(0, coordinator.failures)
            }
    }

    private companion object {
        val STEP = Regex("""^supervisor\(.*?\): (stop|start) \S*/([^/\s:]+)$""")
    }
}
