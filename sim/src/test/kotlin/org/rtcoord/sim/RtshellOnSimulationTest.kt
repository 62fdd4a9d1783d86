package org.rtcoord.sim

import RTC.LifeCycleState
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.runPeer
import org.rtcoord.runtime.RuntimeProcess

/**
 * rtshell drives a system simulated from a saved profile as it drives the fixtures: rtls, rtact, rtdeact, rtcon, rtdis.
 */
class RtshellOnSimulationTest {
    @Test
    fun `rtls lists the simulated components, rtdeact and rtact change them, rtdis and rtcon connect them`() {
        SimulatedSystem.start(savedLocalisation()).use { sim ->
            val host = "/${sim.address}/${RuntimeProcess.hostContext}"
            val listing = runPeer("rtls", "-l", "$host/").ok().output
            for (name in listOf("laser0.rtc", "gyro0.rtc", "odometry0.rtc", "laser_localise0.rtc", "manager.mgr")) {
                assertTrue(listing.lines().any { it.contains(name) }, "rtls -l lists $name:\n$listing")
            }
            assertTrue(listing.lines().first { it.contains("laser0.rtc") }.startsWith("Active"), listing)

            runPeer("rtdeact", "$host/gyro0.rtc").ok()
            assertEquals(LifeCycleState.INACTIVE_STATE, sim.component("gyro0").state)
            runPeer("rtact", "$host/gyro0.rtc").ok()
            assertEquals(LifeCycleState.ACTIVE_STATE, sim.component("gyro0").state)

            val localiser = sim.component("laser_localise0")
            runPeer("rtdis", "$host/laser0.rtc:laser", "$host/laser_localise0.rtc:laser").ok()
            assertTrue(
                localiser.ref
                    .get_ports()
                    .first { it.get_port_profile().name == "laser_localise0.laser" }
                    .get_connector_profiles()
                    .isEmpty()
            )
            runPeer("rtcon", "$host/laser0.rtc:laser", "$host/laser_localise0.rtc:laser").ok()
            val before = localiser.latest("laser")?.timeNanos ?: 0
            await("laser data at the localiser through rtcon's connection") {
                (localiser.latest("laser")?.timeNanos ?: 0) > before
            }
        }
    }
}
