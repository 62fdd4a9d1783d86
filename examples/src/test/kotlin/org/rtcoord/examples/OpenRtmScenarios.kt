package org.rtcoord.examples

import java.nio.file.Paths
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.rtcoord.LifeCycle
import org.rtcoord.PortData
import org.rtcoord.RtcTree
import org.rtcoord.TimedDoubleSeq
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.FailedAction
import org.rtcoord.fixtures.await

/**
 * The paper's coordinator against real OpenRTM-aist managers and components, where the fixtures' fidelity is put to the
 * test: the scenarios [OpenRtmPythonTest] and [OpenRtmCppTest] run on their installations.
 */
object OpenRtmScenarios {
    /** Runs [script] on a tree of a freshly started system on [installation] while [test] runs, then closes all. */
    private fun coordinating(
        installation: OpenRtmInstallation,
        script: String,
        test: suspend (OpenRtmSystem, Coordinator, List<String>) -> Unit,
    ): Unit = runBlocking {
        OpenRtmSystem.start(installation).use { system ->
            val log = CopyOnWriteArrayList<String>()
            val config = TreeConfig(nameServers = listOf(system.naming))
            val coordination = ExampleSystem.scripts.load(Paths.get(script), emptyList(), config)
            RtcTree(config).use { tree ->
                Coordinator(tree, coordination) { line -> log += line.also { println("coordinator: $it") } }
                    .use { coordinator ->
                        coordinator.start()
                        test(system, coordinator, log)
                    }
            }
        }
    }

    /** A tap decodes a real out-port's scans, and its connector leaves with it. */
    fun data(installation: OpenRtmInstallation): Unit = runBlocking {
        OpenRtmSystem.start(installation).use { system ->
            val port = system.witness.port(system.path("laser0.rtc:laser"))
            val scans = Channel<PortData>(Channel.UNLIMITED)
            val tapped = TimeSource.Monotonic.markNow()
            val subscription = port.tap { scans.trySend(it) }
            val scan = withTimeout(10.seconds) { scans.receive() }
            println("${installation.label}: first scan through the tap ${tapped.elapsedNow()} after tapping")
            assertTrue(scan is TimedDoubleSeq && scan.data.size == 8 && scan.data.all { it in 4.0..6.0 }, "$scan")
            fun taps() = runBlocking { port.connections().count { it.id.startsWith("rtcoord-tap-") } }
            assertEquals(1, taps(), "the real port lists the tap's connector")
            subscription.cancel()
            await("the tap's connector to leave the real port", 10.seconds) { taps() == 0 }
        }
    }

    /** A laser that stays broken is replaced by the odometry-gyro localiser a real master creates. */
    fun localisation(installation: OpenRtmInstallation): Unit =
        coordinating(installation, "localisation.coord.kts") { system, coordinator, log ->
            val laser = system.witness.component(system.path("laser0.rtc"))
            val broken = TimeSource.Monotonic.markNow()
            laser.setParameter("broken", "1")

            await("odo_localise0 to be ACTIVE", 30.seconds) {
                runBlocking {
                    runCatching { system.witness.component(system.path("odo_localise0.rtc")).state() }.getOrNull()
                } == LifeCycle.ACTIVE
            }
            println("${installation.label}: persistent laser fault to odo_localise0 ACTIVE in ${broken.elapsedNow()}")
            // OpenRTM's names of the ports at each connection's far end.
            val peers =
                listOf("odo", "gyro").associateWith { port ->
                    system.witness.port(system.path("odo_localise0.rtc:$port")).connections().map {
                        it.ports.first().fullName
                    }
                }
            assertEquals(mapOf("odo" to listOf("odometry0.odo"), "gyro" to listOf("gyro0.gyro")), peers)
            val old = system.witness.component(system.path("laser_localise0.rtc"))
            assertEquals(LifeCycle.INACTIVE, old.state())
            assertTrue(
                listOf("laser", "odo").all {
                    system.witness.port(system.path("laser_localise0.rtc:$it")).connections().isEmpty()
                }
            )
            assertEquals(LifeCycle.ERROR, laser.state(), "the laser stays broken")
            // A real manager's components are bound twice (naming context and manager): either path is laser0.
            val failed = coordinator.failedActions.single()
            assertTrue(failed.action.startsWith("reset /") && failed.action.endsWith("/laser0.rtc"), failed.action)
            assertEquals(
                FailedAction(
                    failed.action,
                    "reset failed: RTC_ERROR (in context 0; still ERROR at its 1000 ms deadline)",
                    bestEffort = true,
                ),
                failed,
            )
            assertEquals(0, coordinator.failures, log.joinToString("\n"))
        }

    /** The slave manager hosting the pipeline is killed, and a real master re-creates it in a slave it starts. */
    fun supervision(installation: OpenRtmInstallation): Unit =
        coordinating(installation, "supervision.coord.kts") { system, coordinator, log ->
            val before = system.witness.component(system.path("laser0.rtc"))
            val killed = TimeSource.Monotonic.markNow()
            system.killSlave()

            for (name in listOf("odometry0", "laser0", "laser_localise0")) {
                await("$name to be re-created and ACTIVE", 60.seconds) {
                    runBlocking {
                        runCatching {
                            system.witness.refresh(
                                system.witness.component(system.path("gyro0.rtc")).path.parent!!,
                                depth = 0,
                            )
                            system.witness.component(system.path("$name.rtc")).state()
                        }
                            .getOrNull()
                    } == LifeCycle.ACTIVE
                }
            }
            println(
                "${installation.label}: slave manager SIGKILL to the pipeline ACTIVE again in ${killed.elapsedNow()}"
            )
            val laser = system.witness.component(system.path("laser0.rtc"))
            assertTrue(!laser.isSameComponent(before), "laser0 is a new component")
            val peers =
                listOf("laser", "odo").associateWith { port ->
                    system.witness.port(system.path("laser_localise0.rtc:$port")).connections().map {
                        it.ports.first().fullName
                    }
                }
            assertEquals(mapOf("laser" to listOf("laser0.laser"), "odo" to listOf("odometry0.odo")), peers)
            assertEquals(1, log.count { it.endsWith("failed together: one restart") }, log.joinToString("\n"))
            assertTrue(log.none { it.startsWith("giving up") }, log.joinToString("\n"))
            assertEquals(0, coordinator.failures, log.joinToString("\n"))
        }

    /** With a laser that stays broken the system runs on odometry, and on the laser again once it is repaired. */
    fun modes(installation: OpenRtmInstallation): Unit =
        coordinating(installation, "modes.coord.kts") { system, coordinator, log ->
            val machine = coordinator.machine("localisation")
            await("the laser mode's network", 30.seconds) {
                log.any { it.startsWith("mode localisation/laser: network done") }
            }
            val laser = system.witness.component(system.path("laser0.rtc"))
            val broken = TimeSource.Monotonic.markNow()
            laser.setParameter("broken", "1")

            await("the odometry localiser to track", 30.seconds) {
                machine.mode.value == "localisation/degraded/odometry/tracking"
            }
            println(
                "${installation.label}: persistent laser fault to the odometry mode tracking in ${broken.elapsedNow()}"
            )
            assertEquals(LifeCycle.ACTIVE, system.witness.component(system.path("odo_localise0.rtc")).state())
            assertEquals(LifeCycle.INACTIVE, system.witness.component(system.path("laser_localise0.rtc")).state())
            assertEquals(LifeCycle.ERROR, laser.state())

            laser.setParameter("broken", "0")
            await("the repaired laser to reset", 30.seconds) { runBlocking { runCatching { laser.reset() }.isSuccess } }
            laser.activate()
            await("the laser mode's network again", 30.seconds) {
                log.count { it.startsWith("mode localisation/laser: network done") } == 2
            }
            assertEquals("localisation/laser", machine.mode.value)
            assertEquals(LifeCycle.ACTIVE, system.witness.component(system.path("laser_localise0.rtc")).state())
            assertEquals(LifeCycle.INACTIVE, system.witness.component(system.path("odo_localise0.rtc")).state())
            assertEquals(0, coordinator.failures, log.joinToString("\n"))
        }
}
