package org.rtcoord.sim

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.nameServerPath
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.runtime.RuntimeProcess

/**
 * A simulation compared with the live system it was saved from: nothing when faithful, one line per difference when
 * not.
 */
class SimulationComparisonTest {
    @Test
    fun `the comparison with the live system finds no difference, and names each one it finds`() = runBlocking {
        TwoSlaveSystem.start().use { live ->
            val saved = live.save()
            live.tree().use { tree ->
                val root = nameServerPath(live.address)
                SimulatedSystem.start(saved).use { sim ->
                    val same = SimulationComparison.of(tree, root, sim)
                    assertEquals(emptyList<String>(), same.differences)
                    assertEquals("7 components, 3 connections, 3 managers", same.compared)
                }
                SimulatedSystem.start(changed(saved)).use { sim ->
                    val host = "/${RuntimeProcess.hostContext}"
                    assertEquals(
                        listOf(
                            "$host/laser0.rtc: execution context 0: rate: 100.0 live, 50.0 simulated",
                            "$host/map_client0.rtc: port map: interfaces: required map (MapServer::Map) live, required map (MapServer::Atlas) simulated",
                            "$host/planner0.rtc: configuration set 'fast': horizon: '3' live, '4' simulated",
                            "connection odometry0.odo -> laser_localise0.odo (odometry0:odo_laser_localise0:odo): one live, none simulated",
                            "slave manager $host/manager.mgr/sensors: components: gyro0, laser0, map_server0, odometry0 live, " +
                                "gyro0, laser0, map_server0, odometry0, planner0 simulated",
                            "slave manager $host/manager.mgr/sensors: types: gyro, laser, map_server, odometry live, gyro, laser, map_server, odometry, planner simulated",
                            "slave manager $host/manager.mgr/localisation: components: laser_localise0, map_client0, planner0 live, laser_localise0, map_client0 simulated",
                        ),
                        SimulationComparison.of(tree, root, sim).differences,
                    )
                }
            }
        }
    }

    /** [saved] with a rate, an interface, a value, a connection and a component's manager changed. */
    private fun changed(saved: RtsProfile): RtsProfile {
        val xml = RtsProfiles.write(saved, ProfileFormat.XML)
        val laser = xml.substringAfter("rts:instanceName=\"laser0\"").substringBefore("</rts:Components>")
        val planner = xml.substringAfter("rts:instanceName=\"planner0\"").substringBefore("</rts:Components>")
        val text =
            xml.replace(laser, laser.replace("rts:rate=\"100.0\"", "rts:rate=\"50.0\""))
                .replace(
                    planner,
                    planner.replace("rts:name=\"horizon\" rts:data=\"3\"", "rts:name=\"horizon\" rts:data=\"4\""),
                )
                .replace(
                    "rtsExt:value=\"MapServer::Map\"/>\n        </rts:ServicePorts>",
                    "rtsExt:value=\"MapServer::Atlas\"/>\n        </rts:ServicePorts>",
                )
        val profile = RtsProfiles.parse(text, ProfileFormat.XML)
        val properties =
            profile.ext.properties +
                mapOf(
                    "rtcoord.slave.1.components" to "laser0,gyro0,odometry0,map_server0,planner0",
                    "rtcoord.slave.2.components" to "laser_localise0,map_client0",
                )
        return profile
            .withExt(profile.ext.withProperties(properties))
            .withDataPortConnectors(profile.dataPortConnectors.filter { it.target.portName != "laser_localise0.odo" })
    }
}
