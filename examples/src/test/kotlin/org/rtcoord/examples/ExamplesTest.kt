package org.rtcoord.examples

import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.CsvSource
import org.junit.jupiter.params.provider.EnumSource
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle
import org.rtcoord.WatchMode
import org.rtcoord.dsl.FailedAction
import org.rtcoord.dsl.Mode
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue
import org.rtcoord.runtime.RuntimeComponent

class ExamplesTest {
    enum class Mode(val options: EventOptions) {
        PUSH(EventOptions(WatchMode.PUSH)),
        POLL(EventOptions(WatchMode.POLL, pollPeriod = 100.milliseconds)),
    }

    /** How the laser fails: once (a reset recovers it), or for good (its resets keep failing). */
    enum class Fault(val laserAfter: LifeCycle, val inject: (RuntimeComponent) -> Unit) {
        TRANSIENT(LifeCycle.INACTIVE, RuntimeComponent::fail),
        PERSISTENT(LifeCycle.ERROR, RuntimeComponent::breakDown),
    }

    @ParameterizedTest
    @CsvSource("PUSH,TRANSIENT", "PUSH,PERSISTENT", "POLL,TRANSIENT", "POLL,PERSISTENT")
    fun `localisation - the laser fails and the odometry-gyro localiser takes over`(mode: Mode, fault: Fault): Unit =
        runBlocking {
            ExampleSystem("localisation.coord.kts", mode.options).use { example ->
                example.coordinator.start()
                val faulted = TimeSource.Monotonic.markNow()
                fault.inject(example.system.component("laser0"))

                await("odo_localise0 to be ACTIVE") {
                    runBlocking {
                        runCatching { example.witness.component(example.path("odo_localise0.rtc")).state() }.getOrNull()
                    } == LifeCycle.ACTIVE
                }
                println(
                    "localisation example ($mode, $fault laser fault): fault to odo_localise0 ACTIVE in ${faulted.elapsedNow()}"
                )
                val created =
                    example.witness.component(example.path("odo_localise0.rtc")).also { it.refresh() }.snapshot()
                assertEquals(
                    mapOf("odo" to 1, "gyro" to 1, "pose" to 0),
                    created.ports.associate { it.name to it.connectors.size },
                )
                val connections =
                    example.witness.port(example.path("odo_localise0.rtc:odo")).connections() +
                        example.witness.port(example.path("odo_localise0.rtc:gyro")).connections()
                assertEquals(
                    setOf(example.path("odometry0.rtc:odo"), example.path("gyro0.rtc:gyro")),
                    connections.map { it.ports.first().path.toString() }.toSet(),
                )
                val old =
                    example.witness.component(example.path("laser_localise0.rtc")).also { it.refresh() }.snapshot()
                assertEquals(LifeCycle.INACTIVE, old.state)
                assertTrue(old.ports.all { it.connectors.isEmpty() })
                assertEquals(fault.laserAfter, example.witness.component(example.path("laser0.rtc")).state())
                assertEquals(0, example.coordinator.failures)
                val resetFailed =
                    FailedAction(
                        "reset ${example.path("laser0.rtc")}",
                        "reset failed: RTC_ERROR (in context 0; still ERROR at its 1000 ms deadline)",
                        bestEffort = true,
                    )
                assertEquals(
                    if (fault == Fault.PERSISTENT) listOf(resetFailed) else emptyList<FailedAction>(),
                    example.coordinator.failedActions,
                )
            }
        }

    @Test
    fun `frozen laser - a laser ACTIVE but silent is noticed from its data and odometry takes over`(): Unit =
        runBlocking {
            ExampleSystem("frozen-laser.coord.kts", Mode.PUSH.options).use { example ->
                example.coordinator.start()
                val laser = example.system.component("laser0")
                val tap =
                    awaitValue("the coordinator's tap on laser0:laser") {
                        runBlocking { example.witness.port(example.path("laser0.rtc:laser")).connections() }
                            .firstOrNull { it.id.startsWith("rtcoord-tap-") }
                    }
                // Longer than the threshold with scans flowing: no switch.
                val watched = TimeSource.Monotonic.markNow()
                val consumer = example.system.component("laser_localise0")
                val first = consumer.latest("laser")
                await("800 ms of scans reaching the laser localiser") {
                    watched.elapsedNow() > 800.milliseconds && consumer.latest("laser") !== first
                }
                assertTrue(
                    example.system.components.none { it.instanceName == "odo_localise0" },
                    "no switch while scans flow",
                )

                val frozen = TimeSource.Monotonic.markNow()
                laser.freezeOutput()
                await("odo_localise0 to be ACTIVE") {
                    runBlocking {
                        runCatching { example.witness.component(example.path("odo_localise0.rtc")).state() }.getOrNull()
                    } == LifeCycle.ACTIVE
                }
                val took = frozen.elapsedNow()
                println("frozen-laser example: freeze to odo_localise0 ACTIVE in $took")
                assertTrue(took >= 500.milliseconds, "not before the 500 ms of silence: $took")
                assertEquals(
                    LifeCycle.ACTIVE,
                    example.witness.component(example.path("laser0.rtc")).state(),
                    "the laser stayed ACTIVE",
                )
                val old =
                    example.witness.component(example.path("laser_localise0.rtc")).also { it.refresh() }.snapshot()
                assertEquals(LifeCycle.INACTIVE, old.state)
                assertTrue(old.ports.all { it.connectors.isEmpty() })
                val localiser = example.system.component("odo_localise0")
                val before = localiser.latest("odo")
                await("the odometry to reach the new localiser") { localiser.latest("odo") !== before }
                assertEquals(0, example.coordinator.failures)
                assertTrue(example.log.any { it.contains("sent no scan for 500 ms") }, example.log.joinToString("\n"))

                example.coordinator.close()
                await("the coordinator's tap removed on close") {
                    runBlocking { example.witness.port(example.path("laser0.rtc:laser")).connections() }
                        .none { it.id == tap.id }
                }
            }
        }

    @Test
    fun `localisation - a coordinator started after the laser broke still switches to odometry (includeCurrent)`():
        Unit = runBlocking {
        ExampleSystem("localisation.coord.kts", Mode.PUSH.options).use { example ->
            example.system.component("laser0").breakDown()
            await("laser0 to be in ERROR before the coordinator starts") {
                example.system.component("laser0").state == RTC.LifeCycleState.ERROR_STATE
            }
            example.coordinator.start()
            await("odo_localise0 to be ACTIVE") {
                runBlocking {
                    runCatching { example.witness.component(example.path("odo_localise0.rtc")).state() }.getOrNull()
                } == LifeCycle.ACTIVE
            }
            assertTrue(
                example.log.any { it.contains("rule 'laser0.rtc is in or enters ERROR' fired") },
                example.log.joinToString("\n"),
            )
            assertEquals(0, example.coordinator.failures)
        }
    }

    @ParameterizedTest
    @EnumSource(Fault::class)
    fun `localisation - a switch the manager refuses is taken back and the laser localiser runs again`(
        fault: Fault
    ): Unit = runBlocking {
        ExampleSystem("localisation.coord.kts", Mode.PUSH.options).use { example ->
            example.system.master!!.remove_slave_manager(example.system.slave!!.ref)
            example.coordinator.start()
            val localiser = example.system.component("laser_localise0")
            fault.inject(example.system.component("laser0"))

            // The rule's failure is counted after its onFailure block finished.
            await("the switch to fail and be taken back") { example.coordinator.failures == 1 }
            assertTrue(
                example.log.any {
                    it.startsWith("the switch to odometry failed") && it.endsWith("back to the laser localiser")
                }
            )
            await("the laser localiser to run again") { localiser.state == RTC.LifeCycleState.ACTIVE_STATE }
            assertEquals(setOf("laser0.laser"), example.peers("laser_localise0.rtc:laser"))
            assertEquals(setOf("odometry0.odo"), example.peers("laser_localise0.rtc:odo"))
            assertTrue(example.system.components.none { it.instanceName == "odo_localise0" })
            if (fault == Fault.TRANSIENT) {
                assertEquals(
                    RTC.LifeCycleState.ACTIVE_STATE,
                    example.system.component("laser0").state,
                    "the laser, reset, runs again",
                )
                val before = localiser.latest("laser")
                await("the laser's data to reach the localiser again") { localiser.latest("laser") !== before }
            } else {
                assertEquals(RTC.LifeCycleState.ERROR_STATE, example.system.component("laser0").state)
                val before = localiser.latest("odo")
                await("the odometry to reach the localiser again") { localiser.latest("odo") !== before }
            }
        }
    }

    @Test
    fun `bounded restart - restarts the gyro three times, then leaves it in ERROR`(): Unit = runBlocking {
        ExampleSystem("bounded-restart.coord.kts", Mode.PUSH.options, args = listOf("3")).use { example ->
            example.coordinator.start()
            val gyro = example.system.component("gyro0")
            repeat(3) { restart ->
                gyro.fail()
                await("restart ${restart + 1}") {
                    example.log.any { it.contains("restart ${restart + 1} of 3") } &&
                        gyro.state == RTC.LifeCycleState.ACTIVE_STATE
                }
            }
            gyro.fail()
            await("the coordinator to give up") { example.log.any { it.contains("failed 4 times") } }
            assertEquals(RTC.LifeCycleState.ERROR_STATE, gyro.state)
        }
    }

    @Test
    fun `bounded restart - a gyro whose reset fails is left in ERROR, and the coordinator says so`(): Unit =
        runBlocking {
            ExampleSystem("bounded-restart.coord.kts", Mode.PUSH.options, args = listOf("3")).use { example ->
                example.coordinator.start()
                val gyro = example.system.component("gyro0")
                gyro.breakDown()
                await("the coordinator to say it leaves the gyro") {
                    example.log.any { it.contains("gyro0 cannot be reset: leaving it in ERROR") }
                }
                assertEquals(RTC.LifeCycleState.ERROR_STATE, gyro.state)
                assertEquals(0, example.coordinator.failures, "a failed reset is expected, not a handler failure")
            }
        }

    @Test
    fun `gain schedule - a gain above 2 switches to the precise set`(): Unit = runBlocking {
        ExampleSystem("gain-schedule.coord.kts", Mode.PUSH.options).use { example ->
            example.coordinator.start()
            val localiser = example.witness.component(example.path("laser_localise0.rtc"))
            localiser.setParameter("gain", "3.0")
            await("the precise set to be active") {
                example.system.component("laser_localise0").activeConfigurationSet == "precise"
            }
            localiser.setParameter("gain", "1.5", set = "precise")
            await("the default set to be active again") {
                example.system.component("laser_localise0").activeConfigurationSet == "default"
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Fault::class)
    fun `modes - the laser fails, the system runs on odometry, and back on the laser once it is active`(
        fault: Fault
    ): Unit = runBlocking {
        ExampleSystem("modes.coord.kts", Mode.PUSH.options).use { example ->
            example.coordinator.start()
            val machine = example.coordinator.machine("localisation")
            await("the laser mode's network") {
                example.log.any { it.startsWith("mode localisation/laser: network done (0 steps") }
            }

            val laser = example.system.component("laser0")
            val faulted = TimeSource.Monotonic.markNow()
            fault.inject(laser)
            await("the odometry localiser to track", timeout = 30.seconds) {
                machine.mode.value == "localisation/degraded/odometry/tracking"
            }
            println(
                "modes example ($fault laser fault): fault to odo_localise0 ACTIVE and tracking in ${faulted.elapsedNow()}"
            )
            assertEquals(
                fault.laserAfter,
                example.witness.component(example.path("laser0.rtc")).state(),
                "reset on entry if it can be",
            )
            assertEquals(RTC.LifeCycleState.INACTIVE_STATE, example.system.component("laser_localise0").state)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, example.system.component("odo_localise0").state)
            assertEquals(setOf("odometry0.odo"), example.peers("odo_localise0.rtc:odo"))
            assertEquals(setOf("gyro0.gyro"), example.peers("odo_localise0.rtc:gyro"))
            assertEquals(
                emptySet<String>(),
                example.peers("laser_localise0.rtc:laser") + example.peers("laser_localise0.rtc:odo"),
            )

            if (fault == Fault.PERSISTENT) {
                laser.repair()
                example.witness.component(example.path("laser0.rtc")).reset()
            }
            example.witness.component(example.path("laser0.rtc")).activate()
            await("the laser mode's network again", timeout = 30.seconds) {
                example.log.count { it.startsWith("mode localisation/laser: network done") } == 2
            }
            assertEquals("localisation/laser", machine.mode.value)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, example.system.component("laser_localise0").state)
            assertEquals(RTC.LifeCycleState.INACTIVE_STATE, example.system.component("odo_localise0").state)
            assertEquals(setOf("laser0.laser"), example.peers("laser_localise0.rtc:laser"))
            assertEquals(setOf("odometry0.odo"), example.peers("laser_localise0.rtc:odo"))
            assertEquals(
                emptySet<String>(),
                example.peers("odo_localise0.rtc:odo") + example.peers("odo_localise0.rtc:gyro"),
            )
            assertEquals(
                listOf("start", "laser0.rtc enters ERROR", "done", "laser0.rtc enters ACTIVE"),
                machine.history.value.map { it.trigger },
            )
            assertEquals(0, example.coordinator.failures)
        }
    }
}
