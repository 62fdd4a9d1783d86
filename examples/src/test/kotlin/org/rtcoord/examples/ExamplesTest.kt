package org.rtcoord.examples

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.EnumSource
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle
import org.rtcoord.RtcPath
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

class ExamplesTest {
    enum class Mode(val options: EventOptions) {
        PUSH(EventOptions(WatchMode.PUSH)),
        POLL(EventOptions(WatchMode.POLL, pollPeriod = 100.milliseconds)),
    }

    @ParameterizedTest
    @EnumSource(Mode::class)
    fun `localisation - the laser fails and the odometry-gyro localiser takes over`(mode: Mode): Unit = runBlocking {
        ExampleSystem("localisation.coord.kts", mode.options).use { example ->
            example.coordinator.start()
            example.system.component("laser0").fail()

            await("odo_localise0 to be ACTIVE") {
                runBlocking { runCatching { example.witness.component(example.path("odo_localise0.rtc")).state() }.getOrNull() } == LifeCycle.ACTIVE
            }
            val created = example.witness.component(example.path("odo_localise0.rtc")).also { it.refresh() }.snapshot()
            assertEquals(mapOf("odo" to 1, "gyro" to 1, "pose" to 0), created.ports.associate { it.name to it.connectors.size })
            val connections = example.witness.port(example.path("odo_localise0.rtc:odo")).connections() +
                example.witness.port(example.path("odo_localise0.rtc:gyro")).connections()
            assertEquals(
                setOf(example.path("odometry0.rtc:odo"), example.path("gyro0.rtc:gyro")),
                connections.map { it.ports.first().path.toString() }.toSet(),
            )
            val old = example.witness.component(example.path("laser_localise0.rtc")).also { it.refresh() }.snapshot()
            assertEquals(LifeCycle.INACTIVE, old.state)
            assertTrue(old.ports.all { it.connectors.isEmpty() })
            assertEquals(LifeCycle.INACTIVE, example.witness.component(example.path("laser0.rtc")).state())
            assertEquals(0, example.coordinator.failures)
        }
    }

    @Test
    fun `bounded restart - restarts the gyro three times, then leaves it in ERROR`(): Unit = runBlocking {
        ExampleSystem("bounded-restart.coord.kts", Mode.PUSH.options, args = listOf("3")).use { example ->
            example.coordinator.start()
            val gyro = example.system.component("gyro0")
            repeat(3) { restart ->
                gyro.fail()
                await("restart ${restart + 1}") { example.log.any { it.contains("restart ${restart + 1} of 3") } && gyro.state == RTC.LifeCycleState.ACTIVE_STATE }
            }
            gyro.fail()
            await("the coordinator to give up") { example.log.any { it.contains("failed 4 times") } }
            assertEquals(RTC.LifeCycleState.ERROR_STATE, gyro.state)
        }
    }

    @Test
    fun `gain schedule - a gain above 2 switches to the precise set`(): Unit = runBlocking {
        ExampleSystem("gain-schedule.coord.kts", Mode.PUSH.options).use { example ->
            example.coordinator.start()
            val localiser = example.witness.component(example.path("laser_localise0.rtc"))
            localiser.setParameter("gain", "3.0")
            await("the precise set to be active") { example.system.component("laser_localise0").activeConfigurationSet == "precise" }
            localiser.setParameter("gain", "1.5", set = "precise")
            await("the default set to be active again") { example.system.component("laser_localise0").activeConfigurationSet == "default" }
        }
    }

    @Test
    fun `modes - the laser fails, the system runs on odometry, and back on the laser once it is active`(): Unit = runBlocking {
        ExampleSystem("modes.coord.kts", Mode.PUSH.options).use { example ->
            example.coordinator.start()
            val machine = example.coordinator.machine("localisation")
            await("the laser mode's network") { example.log.any { it.startsWith("mode localisation/laser: network done (0 steps") } }

            example.system.component("laser0").fail()
            await("the odometry localiser to track", timeout = 30.seconds) { machine.mode.value == "localisation/degraded/odometry/tracking" }
            assertEquals(RTC.LifeCycleState.INACTIVE_STATE, example.system.component("laser0").state, "reset on entry")
            assertEquals(RTC.LifeCycleState.INACTIVE_STATE, example.system.component("laser_localise0").state)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, example.system.component("odo_localise0").state)
            assertEquals(setOf("odometry0.odo"), example.peers("odo_localise0.rtc:odo"))
            assertEquals(setOf("gyro0.gyro"), example.peers("odo_localise0.rtc:gyro"))
            assertEquals(emptySet<String>(), example.peers("laser_localise0.rtc:laser") + example.peers("laser_localise0.rtc:odo"))

            example.witness.component(example.path("laser0.rtc")).activate()
            await("the laser mode's network again", timeout = 30.seconds) { example.log.count { it.startsWith("mode localisation/laser: network done") } == 2 }
            assertEquals("localisation/laser", machine.mode.value)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, example.system.component("laser_localise0").state)
            assertEquals(RTC.LifeCycleState.INACTIVE_STATE, example.system.component("odo_localise0").state)
            assertEquals(setOf("laser0.laser"), example.peers("laser_localise0.rtc:laser"))
            assertEquals(setOf("odometry0.odo"), example.peers("laser_localise0.rtc:odo"))
            assertEquals(emptySet<String>(), example.peers("odo_localise0.rtc:odo") + example.peers("odo_localise0.rtc:gyro"))
            assertEquals(
                listOf("start", "laser0.rtc enters ERROR", "done", "laser0.rtc enters ACTIVE"),
                machine.history.value.map { it.trigger },
            )
            assertEquals(0, example.coordinator.failures)
        }
    }

    @Test
    fun `supervision - a laser that exits is re-created and reconnected, the localiser restarted after it, and past the limit the localiser stops`(): Unit = runBlocking {
        ExampleSystem("supervision.coord.kts", Mode.PUSH.options, args = listOf("1")).use { example ->
            example.coordinator.start()
            val (odometry, exited, localiser) = listOf("odometry0", "laser0", "laser_localise0").map(example.system::component)
            example.witness.component(example.path("laser0.rtc")).exit()

            val laser = awaitValue("laser0 to be re-created and active") {
                example.system.runtime.components.firstOrNull { it.instanceName == "laser0" && it !== exited && it.state == RTC.LifeCycleState.ACTIVE_STATE }
            }
            await("the localiser to be restarted after it") { example.log.any { it.endsWith("activate ${example.path("laser_localise0.rtc")}") } }
            val steps = example.log.filter { ": stop " in it || ": start " in it }.map { it.substringAfter("): ").substringBefore(" /") + " " + it.substringAfterLast('/') }
            assertEquals(listOf("stop laser_localise0.rtc", "start laser0.rtc", "start laser_localise0.rtc"), steps)
            val before = localiser.latest("laser")
            await("the new laser's data to reach the localiser") { localiser.latest("laser") !== before }
            example.witness.refresh(RtcPath.parse(example.path("laser0.rtc")).parent!!, depth = 0)
            val connections = example.witness.port(example.path("laser0.rtc:laser")).connections()
            assertEquals(listOf(example.path("laser_localise0.rtc:laser")), connections.map { it.ports.last().path.toString() })
            assertEquals(1, example.witness.port(example.path("laser_localise0.rtc:laser")).connections().size, "no stale connector left")
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, odometry.state)

            laser.fail()
            await("the supervisor to give up and stop the localiser") {
                example.log.any { it.startsWith("giving up: ${example.path("laser0.rtc")} entered ERROR after 1 restarts") } &&
                    localiser.state == RTC.LifeCycleState.INACTIVE_STATE
            }
            assertEquals(RTC.LifeCycleState.ERROR_STATE, laser.state)
            assertEquals(0, example.coordinator.failures)
        }
    }
}
