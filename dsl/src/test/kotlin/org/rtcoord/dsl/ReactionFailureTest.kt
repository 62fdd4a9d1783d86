package org.rtcoord.dsl

import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.fixtures.await

/** Best-effort actions, and what a handler that fails half way does about what it already changed. */
class ReactionFailureTest : CoordinatedSystem() {
    private val laserPath = path("laser0.rtc")

    @Test
    fun `an attempted reset of a component that stays broken is a warning, and the handler goes on`(): Unit =
        runBlocking {
            val outcome = CopyOnWriteArrayList<Boolean>()
            coordinator {
                on(component("laser0")).state(ERROR) {
                    outcome += attempt { reset() }
                    component("laser_localise0").deactivate()
                }
            }
                .use { coordinator ->
                    coordinator.start()
                    system.component("laser0").breakDown()
                    await("the handler to go on past the failed reset") {
                        system.component("laser_localise0").state == RTC.LifeCycleState.INACTIVE_STATE
                    }
                    assertEquals(listOf(false), outcome)
                    assertEquals(RTC.LifeCycleState.ERROR_STATE, system.component("laser0").state)
                    assertEquals(0, coordinator.failures, "a best effort that fails is no handler failure")
                    assertEquals(
                        listOf(
                            FailedAction(
                                "reset $laserPath",
                                "reset failed: RTC_ERROR (in context 0; still ERROR at its 3000 ms deadline)",
                                bestEffort = true,
                            )
                        ),
                        coordinator.failedActions,
                    )
                    assertTrue(
                        log.any {
                            it.startsWith("warning: $laserPath: reset failed: RTC_ERROR") &&
                                it.endsWith("going on (attempt)")
                        },
                        "$log",
                    )
                }
        }

    @Test
    fun `a failing action outside attempt stops the handler and is listed as failed`(): Unit = runBlocking {
        coordinator {
            on(component("laser0")).state(ERROR) {
                reset()
                component("laser_localise0").deactivate()
            }
        }
            .use { coordinator ->
                coordinator.start()
                system.component("laser0").breakDown()
                await("the handler to fail") { coordinator.failures == 1 }
                assertEquals(
                    RTC.LifeCycleState.ACTIVE_STATE,
                    system.component("laser_localise0").state,
                    "the handler stopped at the reset",
                )
                assertEquals(
                    listOf(
                        FailedAction(
                            "reset $laserPath",
                            "reset failed: RTC_ERROR (in context 0; still ERROR at its 3000 ms deadline)",
                            bestEffort = false,
                        )
                    ),
                    coordinator.failedActions,
                )
            }
    }

    @Test
    fun `a switch the manager refuses half way is undone - the old localiser runs again, connected as before`(): Unit =
        runBlocking {
            val failures = CopyOnWriteArrayList<ReactionFailure>()
            system.master!!.remove_slave_manager(system.slave!!.ref)
            coordinator {
                on(component("laser0")).state(ERROR) {
                    attempt { reset() }
                    onFailure { failure ->
                        failures += failure
                        failure.undo()
                        attempt { activate() }
                    }
                    component("laser_localise0").run {
                        disconnectAll()
                        deactivate()
                    }
                    val localiser = manager().create("odo_localise")
                    connect("odometry0:odo", localiser.port("odo"))
                    localiser.activate()
                }
            }
                .use { coordinator ->
                    coordinator.start()
                    system.component("laser0").fail()
                    await("the handler to fail and its fallback to finish") { coordinator.failures == 1 }
                    val failure = failures.single()
                    assertEquals(
                        listOf("reset", "disconnect all", "deactivate"),
                        failure.done.map { it.substringBefore(" /") },
                    )
                    val localiser = system.component("laser_localise0")
                    assertEquals(RTC.LifeCycleState.ACTIVE_STATE, localiser.state)
                    assertEquals(RTC.LifeCycleState.ACTIVE_STATE, system.component("laser0").state)
                    val peers =
                        localiser.ref.get_ports().flatMap { port ->
                            port.get_connector_profiles().flatMap { c -> c.ports.map { it.get_port_profile().name } }
                        }
                    assertEquals(
                        setOf("laser0.laser", "odometry0.odo", "laser_localise0.laser", "laser_localise0.odo"),
                        peers.toSet(),
                    )
                    assertEquals(
                        2,
                        localiser.ref.get_ports().sumOf { it.get_connector_profiles().size },
                        "one connection on each in-port",
                    )
                    val before = localiser.latest("laser")
                    await("the laser's data to reach the localiser again") { localiser.latest("laser") !== before }
                    assertTrue(log.contains("not undone: reset $laserPath"), "$log")
                }
        }

    @Test
    fun `onFailure outside a handler fails at once, naming where it works`(): Unit = runBlocking {
        coordinator {
            modes("m") {
                initial("a")
                mode("a") { entry { onFailure {} } }
            }
        }
            .use { coordinator ->
                coordinator.start()
                await("the entry action to fail") { coordinator.failures == 1 }
                assertTrue(
                    log.any { it.contains("onFailure works in rule handlers, timers and escalation handlers") },
                    "$log",
                )
            }
    }
}
