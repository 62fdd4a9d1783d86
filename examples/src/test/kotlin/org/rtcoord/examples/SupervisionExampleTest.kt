package org.rtcoord.examples

import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.RtcPath
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue

/**
 * examples/supervision.coord.kts on the localisation system: a class of its own, as its scenarios are the examples'
 * longest, so that the build's two test JVMs run them beside the other examples'.
 */
class SupervisionExampleTest {
    @Test
    fun `supervision - a laser that exits is re-created and reconnected, the localiser restarted after it, and past the limit the localiser stops`():
        Unit = runBlocking {
        ExampleSystem("supervision.coord.kts", ExamplesTest.Mode.PUSH.options, args = listOf("1")).use { example ->
            example.coordinator.start()
            val (odometry, exited, localiser) =
                listOf("odometry0", "laser0", "laser_localise0").map(example.system::component)
            example.witness.component(example.path("laser0.rtc")).exit()

            val laser =
                awaitValue("laser0 to be re-created and active") {
                    example.system.runtime.components.firstOrNull {
                        it.instanceName == "laser0" && it !== exited && it.state == RTC.LifeCycleState.ACTIVE_STATE
                    }
                }
            await("the localiser to be restarted after it") {
                example.log.any { it.endsWith("activate ${example.path("laser_localise0.rtc")}") }
            }
            val steps =
                example.log
                    .filter { ": stop " in it || ": start " in it }
                    .map { it.substringAfter("): ").substringBefore(" /") + " " + it.substringAfterLast('/') }
            assertEquals(listOf("stop laser_localise0.rtc", "start laser0.rtc", "start laser_localise0.rtc"), steps)
            val before = localiser.latest("laser")
            await("the new laser's data to reach the localiser") { localiser.latest("laser") !== before }
            example.witness.refresh(RtcPath(example.path("laser0.rtc")).parent!!, depth = 0)
            val connections = example.witness.port(example.path("laser0.rtc:laser")).connections()
            assertEquals(
                listOf(example.path("laser_localise0.rtc:laser")),
                connections.map { it.ports.last().path.toString() },
            )
            assertEquals(
                1,
                example.witness.port(example.path("laser_localise0.rtc:laser")).connections().size,
                "no stale connector left",
            )
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, odometry.state)

            laser.fail()
            await("the supervisor to give up and stop the localiser") {
                example.log.any {
                    it.startsWith("giving up: ${example.path("laser0.rtc")} entered ERROR after 1 restarts")
                } && localiser.state == RTC.LifeCycleState.INACTIVE_STATE
            }
            assertEquals(RTC.LifeCycleState.ERROR_STATE, laser.state)
            await("the localisation to go on from odometry") {
                example.system.components.any {
                    it.instanceName == "odo_localise0" && it.state == RTC.LifeCycleState.ACTIVE_STATE
                }
            }
            assertEquals(0, example.coordinator.failures)
        }
    }

    @Test
    fun `supervision - a laser that stays broken cannot be restarted, and the localisation goes on from odometry`():
        Unit = runBlocking {
        ExampleSystem("supervision.coord.kts", ExamplesTest.Mode.PUSH.options, args = listOf("2")).use { example ->
            example.coordinator.start()
            val (odometry, laser, localiser) =
                listOf("odometry0", "laser0", "laser_localise0").map(example.system::component)
            val faulted = TimeSource.Monotonic.markNow()
            laser.breakDown()

            await("the supervisor to give up on the laser", timeout = 30.seconds) {
                example.log.any { it.startsWith("giving up: ${example.path("laser0.rtc")}") }
            }
            await("the odometry localiser to run") {
                example.system.components.any {
                    it.instanceName == "odo_localise0" && it.state == RTC.LifeCycleState.ACTIVE_STATE
                }
            }
            println(
                "supervision example (persistent laser fault, 2 restarts allowed): fault to odo_localise0 ACTIVE in ${faulted.elapsedNow()}"
            )
            assertEquals(setOf("odometry0.odo"), example.peers("odo_localise0.rtc:odo"))
            assertEquals(setOf("gyro0.gyro"), example.peers("odo_localise0.rtc:gyro"))
            assertEquals(RTC.LifeCycleState.INACTIVE_STATE, localiser.state)
            assertEquals(
                emptySet<String>(),
                example.peers("laser_localise0.rtc:laser") + example.peers("laser_localise0.rtc:odo"),
            )
            assertEquals(RTC.LifeCycleState.ERROR_STATE, laser.state)
            assertEquals(RTC.LifeCycleState.ACTIVE_STATE, odometry.state, "restForOne leaves the odometry alone")
            assertEquals(0, example.coordinator.failures)
        }
    }

    @Test
    fun `supervision - the slave manager hosting the pipeline is killed, and the master re-creates it in another slave, connected and active`():
        Unit = runBlocking {
        ExampleSystem(
                "supervision.coord.kts",
                ExamplesTest.Mode.PUSH.options,
                pipeline = ExampleSystem.Pipeline.SEPARATE_PROCESS,
            )
            .use { example ->
                example.coordinator.start()
                val killed = TimeSource.Monotonic.markNow()
                example.pipelineProcess!!.kill()

                val pipeline =
                    listOf("odometry0", "laser0", "laser_localise0").map { name ->
                        awaitValue("$name to be re-created through the master and active", 30.seconds) {
                            example.system.runtime.components.firstOrNull {
                                it.instanceName == name && !it.isExited && it.state == RTC.LifeCycleState.ACTIVE_STATE
                            }
                        }
                    }
                println(
                    "supervision example: slave manager SIGKILL to the pipeline ACTIVE again in another slave in ${killed.elapsedNow()}"
                )
                val localiser = pipeline.last()
                await("the localiser to get laser and odometry data again") {
                    localiser.latest("laser") != null && localiser.latest("odo") != null
                }
                example.witness.refresh(RtcPath(example.path("laser0.rtc")).parent!!, depth = 0)
                assertEquals(setOf("laser0.laser"), example.peers("laser_localise0.rtc:laser"))
                assertEquals(setOf("odometry0.odo"), example.peers("laser_localise0.rtc:odo"))
                assertEquals(
                    1,
                    example.log.count { it.endsWith("failed together: one restart") },
                    example.log.joinToString("\n"),
                )
                assertTrue(example.log.none { it.startsWith("giving up") }, example.log.joinToString("\n"))
                assertEquals(
                    RTC.LifeCycleState.ACTIVE_STATE,
                    example.system.component("gyro0").state,
                    "the gyro, in another process, is left alone",
                )
                assertEquals(0, example.coordinator.failures)
            }
    }
}
