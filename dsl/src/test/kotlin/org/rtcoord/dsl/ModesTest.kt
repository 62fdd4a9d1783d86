package org.rtcoord.dsl

import RTC.LifeCycleState
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.TimeSource
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle.ACTIVE
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.ParameterChanged
import org.rtcoord.StateChanged
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.Behaviour
import org.rtcoord.runtime.ComponentContext
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.Scenarios

/**
 * Mode machines driving the localisation system over IIOP; results are read back through the fixtures and a second
 * tree.
 */
class ModesTest : CoordinatedSystem() {
    // Copy-on-write: the tests iterate it while the coordinator appends.
    private val trace = CopyOnWriteArrayList<String>()

    private suspend fun peers(port: String): Set<String> =
        witness
            .port(path(port))
            .connections()
            .flatMap { connection -> connection.ports.map { it.fullName } }
            .filter { !it.startsWith(port.substringBefore(".rtc")) }
            .toSet()

    /** Starts the coordinator and waits until machine [name] is in [mode]. */
    private suspend fun Coordinator.started(name: String, mode: String): RunningMachine {
        start()
        return machine(name).also { machine -> await("$name to start in $mode") { machine.mode.value == mode } }
    }

    private fun ModeBuilder.traced(name: String) {
        entry { trace += "enter $name" }
        exit { trace += "exit $name" }
    }

    @Test
    fun `a mode switch reshapes the network in dependency order and reports done`(): Unit = runBlocking {
        system.runtime.create(Scenarios.odoLocalise, "odo_localise0")
        coordinator {
            modes("localisation") {
                initial("laser")
                mode("laser") {
                    network {
                        active("laser0", "laser_localise0")
                        inactive("odo_localise0")
                        connected("laser0:laser", "laser_localise0:laser")
                        connected("odometry0:odo", "laser_localise0:odo")
                    }
                    on(component("laser0")).state(ERROR) goTo "odometry"
                }
                mode("odometry") {
                    network {
                        inactive("laser_localise0")
                        disconnected("laser0:laser", "laser_localise0:laser")
                        disconnected("odometry0:odo", "laser_localise0:odo")
                        configSet("odo_localise0", "precise")
                        connected("odometry0:odo", "odo_localise0:odo")
                        connected("gyro0:gyro", "odo_localise0:gyro")
                        active("odo_localise0")
                    }
                    initial("switching")
                    mode("switching") {
                        on(done) goTo "running"
                        on(failed) goTo "stranded"
                    }
                    mode("running")
                    mode("stranded")
                }
            }
        }
            .use { coordinator ->
                coordinator.start()
                val machine = coordinator.machine("localisation")
                await("the start's network to be checked") {
                    log.any { it.startsWith("mode localisation/laser: network done (0 steps in ") }
                }
                assertEquals("localisation/laser", machine.mode.value)

                system.component("laser0").fail()
                await("the odometry mode to run", timeout = kotlin.time.Duration.parse("20s")) {
                    machine.mode.value != "localisation/odometry/switching" &&
                        machine.mode.value?.startsWith("localisation/odometry") == true
                }
                assertEquals("localisation/odometry/running", machine.mode.value, log.toString())
                assertEquals(
                    listOf(
                        null to "localisation/laser",
                        "localisation/laser" to "localisation/odometry/switching",
                        "localisation/odometry/switching" to "localisation/odometry/running",
                    ),
                    machine.history.value.map { it.from to it.to },
                )
                assertEquals(listOf("start", "laser0 enters ERROR", "done"), machine.history.value.map { it.trigger })
                assertTrue(
                    log.contains("mode localisation/laser -> localisation/odometry/switching on laser0 enters ERROR"),
                    log.toString(),
                )
                assertTrue(
                    log.any { it.startsWith("mode localisation/odometry/switching: network done (7 steps in ") },
                    log.toString(),
                )

                // The steps ran in dependency order: stop, cut, configure, wire, start.
                val order =
                    listOf(
                        "deactivate /",
                        "disconnect ",
                        "disconnect ",
                        "activate configuration set precise",
                        "connect ",
                        "connect ",
                        "activate /",
                    )
                val steps =
                    log.dropWhile { !it.startsWith("mode localisation/odometry/switching: bringing") }
                        .drop(1)
                        .take(order.size)
                order.zip(steps).forEach { (expected, line) ->
                    assertTrue(line.startsWith(expected), "$expected... expected in order, got $steps")
                }

                // Read back independently: the fixtures' own state, a second tree, and data flowing on the new wires.
                assertEquals(LifeCycleState.INACTIVE_STATE, system.component("laser_localise0").state)
                assertEquals(LifeCycleState.ACTIVE_STATE, system.component("odo_localise0").state)
                assertEquals("precise", system.component("odo_localise0").activeConfigurationSet)
                assertEquals(setOf("odometry0.odo"), peers("odo_localise0.rtc:odo"))
                assertEquals(setOf("gyro0.gyro"), peers("odo_localise0.rtc:gyro"))
                assertEquals(emptySet<String>(), peers("laser_localise0.rtc:laser") + peers("laser_localise0.rtc:odo"))
                await("gyro samples to reach odo_localise0") {
                    system.component("odo_localise0").latest("gyro") != null
                }
                assertEquals(0, coordinator.failures)
            }
    }

    @Test
    fun `a reconfiguration that fails reports the step, the object and why`(): Unit = runBlocking {
        system.runtime.create(Scenarios.odoLocalise, "odo_localise0")
        coordinator {
            modes("m") {
                initial("idle")
                mode("idle") { on(component("gyro0")).state(ERROR) goTo "miswired" }
                mode("miswired") {
                    // The gyro's TimedDouble cannot feed the localiser's TimedDoubleSeq laser input.
                    network {
                        inactive("odometry0")
                        connected("gyro0:gyro", "laser_localise0:laser")
                        active("odo_localise0")
                    }
                    on(failed) goTo "missing"
                }
                mode("missing") {
                    network { active("ghost0") }
                    on(failed) goTo "stuck"
                }
                mode("stuck") {
                    network { active("gyro0") }
                    on(failed) goTo "halted"
                }
                mode("halted")
            }
        }
            .use { coordinator ->
                val machine = coordinator.started("m", "m/idle")
                system.component("gyro0").fail()
                await("the machine to halt", timeout = kotlin.time.Duration.parse("30s")) {
                    machine.mode.value == "m/halted"
                }

                val triggers = machine.history.value.map { it.trigger }
                assertEquals(5, triggers.size, triggers.toString())
                assertTrue(
                    triggers[2].startsWith("failed: connect gyro0.rtc:gyro to laser_localise0.rtc:laser: ") &&
                        "incompatible data types" in triggers[2],
                    triggers[2],
                )
                assertTrue(
                    triggers[3].startsWith("failed: read the state of ghost0.rtc: ghost0.rtc: no such component"),
                    triggers[3],
                )
                assertTrue(
                    triggers[4].startsWith("failed: activate gyro0.rtc: ") && "ERROR" in triggers[4],
                    triggers[4],
                )

                // It stopped at the failing step: the step before it was applied, the one after it was not.
                assertEquals(LifeCycleState.INACTIVE_STATE, system.component("odometry0").state)
                assertEquals(setOf("laser0.laser"), peers("laser_localise0.rtc:laser"))
                assertEquals(LifeCycleState.INACTIVE_STATE, system.component("odo_localise0").state)
                assertEquals(LifeCycleState.ERROR_STATE, system.component("gyro0").state)
            }
    }

    @Test
    fun `a component that exited is neither active nor connected while its name still reaches it`(): Unit =
        runBlocking {
            // OpenRTM-aist unbinds an exited component's name at its manager's next clean-up; until then the name
            // reaches an object that no longer exists.
            system.runtime.cleanupDelay = 1.hours
            coordinator {
                modes("m") {
                    initial("idle")
                    mode("idle") { on(component("gyro0")).state(ERROR) goTo "without" }
                    mode("without") {
                        network {
                            inactive("laser_localise0")
                            disconnected("laser0:laser", "laser_localise0:laser")
                        }
                        on(failed) goTo "failed"
                    }
                    mode("failed")
                }
            }
                .use { coordinator ->
                    val machine = coordinator.started("m", "m/idle")
                    system.component("laser_localise0").exit()
                    system.component("gyro0").fail()
                    await("the network without laser_localise0 to be done or fail") {
                        log.any { it.startsWith("mode m/without: network done") } || machine.mode.value == "m/failed"
                    }
                    assertEquals("m/without", machine.mode.value, log.joinToString("\n"))
                }
        }

    @Test
    fun `a step that misses its deadline fails the network`(): Unit = runBlocking {
        coordinator {
            modes("m") {
                initial("idle")
                mode("idle") { on(component("gyro0")).state(ERROR) goTo "stopping" }
                mode("stopping") {
                    network {
                        stepDeadline = 300.milliseconds
                        inactive("odometry0")
                    }
                    on(failed) goTo "stuck"
                }
                mode("stuck")
            }
        }
            .use { coordinator ->
                val machine = coordinator.started("m", "m/idle")
                val odometry = system.component("odometry0")
                odometry.hang()
                try {
                    system.component("gyro0").fail()
                    await("the network to fail") { machine.mode.value == "m/stuck" }
                    assertEquals(
                        "failed: read the state of odometry0.rtc: did not finish within 300ms",
                        machine.history.value.last().trigger,
                    )
                } finally {
                    odometry.release()
                }
            }
    }

    @Test
    fun `nested modes enter outer to inner and exit inner to outer, deepest transition first`(): Unit = runBlocking {
        coordinator {
            modes("robot") {
                entry { trace += "enter robot" }
                initial("operating")
                mode("operating") {
                    traced("operating")
                    initial("navigating")
                    // Outer transitions: taken in any sub-mode unless a deeper mode takes the event first.
                    on(component("laser0")).state(ERROR) goTo "stopped"
                    on(component("gyro0")).state(ERROR).goTo("stopped") { trace += "action gyro" }
                    mode("navigating") {
                        traced("navigating")
                        initial("planning")
                        mode("planning") {
                            traced("planning")
                            on(component("laser0"))
                                .state(ERROR)
                                .where { (event as StateChanged).old == ACTIVE }
                                .goTo("docking") { trace += "action laser" }
                        }
                    }
                    mode("docking") { traced("docking") }
                }
                mode("stopped") {
                    traced("stopped")
                    on(component("laser0")).state(ERROR).where { false } goTo "operating"
                }
            }
        }
            .use { coordinator ->
                val machine = coordinator.started("robot", "robot/operating/navigating/planning")
                assertEquals(
                    listOf("enter robot", "enter operating", "enter navigating", "enter planning"),
                    trace.toList(),
                )

                system.component("laser0").fail()
                await("docking") { machine.mode.value == "robot/operating/docking" }
                system.component("gyro0").fail()
                await("stopped") { machine.mode.value == "robot/stopped" }
                assertEquals(
                    listOf(
                        "enter robot",
                        "enter operating",
                        "enter navigating",
                        "enter planning",
                        "exit planning",
                        "exit navigating",
                        "action laser",
                        "enter docking",
                        "exit docking",
                        "exit operating",
                        "action gyro",
                        "enter stopped",
                    ),
                    trace.toList(),
                )
                assertEquals(0, machine.unconsumed)

                // In stopped, a laser failure meets only a guard that does not hold: counted, not dropped unseen.
                tree.componentNamed("laser0").reset()
                tree.componentNamed("laser0").activate()
                system.component("laser0").fail()
                await("the unconsumed event to be counted") { machine.unconsumed == 1 }
                assertEquals("robot/stopped", machine.mode.value)
                assertEquals(
                    listOf("start", "laser0 enters ERROR", "gyro0 enters ERROR"),
                    machine.history.value.map { it.trigger },
                )
                assertEquals(0, coordinator.failures)
            }
    }

    @Test
    fun `a network removed or failing under a mode raises networkBroken, logged with what broke`(): Unit = runBlocking {
        coordinator {
            modes("m") {
                initial("tracking")
                mode("tracking") {
                    network {
                        active("laser0", "laser_localise0")
                        connected("laser0:laser", "laser_localise0:laser")
                    }
                    on(networkBroken) goTo "repairing"
                }
                mode("repairing") {
                    network {
                        active("laser0", "laser_localise0")
                        connected("laser0:laser", "laser_localise0:laser")
                    }
                    on(done) goTo "tracking"
                    on(failed) goTo "stranded"
                }
                mode("stranded")
            }
        }
            .use { coordinator ->
                val machine = coordinator.started("m", "m/tracking")
                await("the start's network to be done") { log.any { it.startsWith("mode m/tracking: network done") } }

                // Another client removes the connection: the machine repairs it.
                val laser = witness.port(path("laser0.rtc:laser"))
                laser.disconnect(laser.connections().single().id)
                await("the network to be repaired") { machine.history.value.size == 3 }
                assertEquals(listOf("m/tracking", "m/repairing", "m/tracking"), machine.history.value.map { it.to })
                assertEquals(
                    "networkBroken: laser0.rtc:laser -> laser_localise0.rtc:laser was disconnected",
                    machine.history.value[1].trigger,
                )
                assertTrue(
                    log.contains(
                        "mode m/tracking: network broken: laser0.rtc:laser -> laser_localise0.rtc:laser was disconnected"
                    ),
                    log.toString(),
                )
                await("the connection to be made again") {
                    runBlocking { peers("laser_localise0.rtc:laser") } == setOf("laser0.laser")
                }

                // The laser fails: the repair cannot activate it.
                await("the repaired network to be done") {
                    log.count { it.startsWith("mode m/tracking: network done") } == 2
                }
                system.component("laser0").fail()
                await("the machine to be stranded", timeout = kotlin.time.Duration.parse("20s")) {
                    machine.mode.value == "m/stranded"
                }
                assertEquals("networkBroken: laser0.rtc enters ERROR", machine.history.value[3].trigger)
                assertTrue(log.contains("mode m/tracking: network broken: laser0.rtc enters ERROR"), log.toString())
                assertEquals(0, coordinator.failures)
            }
    }

    @Test
    fun `the death of the process hosting a mode's components raises networkBroken`(): Unit = runBlocking {
        val process =
            FixtureProcess.start(
                "--naming",
                naming.address,
                "--scenario",
                "components:laser1=laser,localise1=laser_localise",
                "--master",
                system.master!!.runtime.orb.corbaloc("manager"),
            )
        process.use {
            coordinator(EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds)) {
                    modes("m") {
                        initial("tracking")
                        mode("tracking") {
                            network {
                                active("laser1", "localise1")
                                connected("laser1:laser", "localise1:laser")
                            }
                            on(networkBroken) goTo "blind"
                        }
                        mode("blind")
                    }
                }
                .use { coordinator ->
                    val machine = coordinator.started("m", "m/tracking")
                    await("the network to be done") {
                        log.any { it.startsWith("mode m/tracking: network done (3 steps") }
                    }
                    val killed = TimeSource.Monotonic.markNow()
                    process.kill()
                    await("the machine to notice", timeout = kotlin.time.Duration.parse("20s")) {
                        machine.mode.value == "m/blind"
                    }
                    println("slave SIGKILL to networkBroken taken: ${killed.elapsedNow()}")
                    val trigger = machine.history.value.last().trigger
                    assertTrue(
                        trigger.startsWith("networkBroken: laser1.rtc ") ||
                            trigger.startsWith("networkBroken: localise1.rtc "),
                        trigger,
                    )
                    assertTrue(log.any { it.startsWith("mode m/tracking: network broken: ") }, log.toString())
                }
        }
    }

    @Test
    fun `what another client already did is not an error, a failed step is planned again from a fresh read`(): Unit =
        runBlocking {
            val odoLocaliser = system.runtime.create(Scenarios.odoLocalise, "odo_localise0")
            // A component whose deactivation does, as another client, what the configurator's later steps would.
            val tripwire =
                ComponentType(
                    "tripwire",
                    behaviour = {
                        object : Behaviour {
                            override fun onDeactivated(rtc: ComponentContext): Boolean {
                                system.component("laser0").ref.get_ports().forEach { it.disconnect_all() }
                                odoLocaliser.activate()
                                return true
                            }
                        }
                    },
                )
            system.runtime.create(tripwire, "tripwire0").activate()
            coordinator {
                modes("m") {
                    initial("idle")
                    mode("idle") { on(component("gyro0")).state(ERROR) goTo "switching" }
                    mode("switching") {
                        network {
                            inactive("tripwire0")
                            disconnected("laser0:laser", "laser_localise0:laser")
                            active("odo_localise0")
                        }
                        on(done) goTo "running"
                        on(failed) goTo "stranded"
                    }
                    mode("running")
                    mode("stranded")
                }
            }
                .use { coordinator ->
                    val machine = coordinator.started("m", "m/idle")
                    system.component("gyro0").fail()
                    await("the switch to end") {
                        machine.mode.value == "m/running" || machine.mode.value == "m/stranded"
                    }
                    assertEquals("m/running", machine.mode.value, log.joinToString("\n"))
                    assertTrue(
                        log.any {
                            it.startsWith("network: disconnect laser0.rtc:laser from laser_localise0.rtc:laser: ") &&
                                it.endsWith("read again: nothing left to do")
                        },
                        log.joinToString("\n"),
                    )
                    assertEquals(emptySet<String>(), peers("laser_localise0.rtc:laser"))
                    assertEquals(LifeCycleState.ACTIVE_STATE, odoLocaliser.state)
                }
        }

    @Test
    fun `a configuration set switch by another client fires the parameter's rule with the set's name, and the switch's own trigger`():
        Unit = runBlocking {
        val seen = CopyOnWriteArrayList<String>()
        coordinator {
            on(component("laser_localise0")).configParam("gain") { old, new ->
                seen += "gain ${(event as ParameterChanged).set}: $old -> $new"
            }
            on(component("laser_localise0")).configSetActivated { old, new -> seen += "set $old -> $new" }
        }
            .use { coordinator ->
                coordinator.start()
                val localiser = witness.component(path("laser_localise0.rtc"))
                localiser.setParameter("gain", "3.0", set = "precise")
                localiser.activateConfigurationSet("precise")
                await("both rules to fire") { seen.size == 2 }
                assertEquals(
                    setOf("gain precise: 1.0 -> 3.0", "set default -> precise"),
                    seen.toSet(),
                    "a change in a set not in force is no change of the gain",
                )

                localiser.setParameter("gain", "1.0", set = "precise")
                await("the change in force to fire the rule") { seen.size == 3 }
                assertEquals("gain precise: 3.0 -> 1.0", seen.last())
                localiser.activateConfigurationSet("default")
                await("the switch to fire") { seen.size == 4 }
                assertEquals("set precise -> default", seen.last(), "the same gain in both sets: no change of the gain")
                assertEquals(0, coordinator.failures)
            }
    }
}
