package org.rtcoord.sim

import RTC.LifeCycleState
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles

/** What a profile names that cannot be simulated is one line each, naming the element and the reason; the rest runs. */
class BadProfileTest {
    private val saved = TwoSlaveSystem.start().use { it.save() }

    @Test
    fun `slaves that cannot be followed, twice-hosted and unknown components, broken types and connectors are each one warning`() {
        val xml = RtsProfiles.write(saved, ProfileFormat.XML)
        val gyro = xml.substringAfter("rts:instanceName=\"gyro0\"").substringBefore("</rts:Components>")
        val doubled = gyro.substringAfter(">").substringBefore("<rts:ConfigurationSets").trim()
        val broken =
            RtsProfiles.parse(
                xml.replace(gyro, gyro.replace(doubled, "$doubled\n$doubled"))
                    .replace("rts:portName=\"laser_localise0.odo\"", "rts:portName=\"laser_localise0.odometry\""),
                ProfileFormat.XML,
            )
        val profile =
            broken.withProperties(
                "rtcoord.slave.2.components" to "laser_localise0,map_client0,planner0,laser0,ghost0",
                "rtcoord.slave.3.types" to "laser",
            )
        SimulatedSystem.start(profile).use { sim ->
            assertEquals(
                listOf(
                    "component gyro0: gyro declares ports [gyro] twice: left out",
                    "rtcoord.slave.2.components: laser0 is hosted by rtcoord.slave.1.components already",
                    "rtcoord.slave.2.components: no component ghost0 in the profile to host",
                    "rtcoord.slave.3: no name (rtcoord.slave.3.name): its components run without a manager",
                    "connector odometry0:odo_laser_localise0:odo: laser_localise0 has no port laser_localise0.odometry: left out",
                ),
                sim.warnings,
            )
            assertEquals(listOf(noPorts("gyro"), noPorts("odo_localise")), sim.notes)
            assertEquals(
                listOf("laser0", "odometry0", "map_server0", "laser_localise0", "map_client0", "planner0").sorted(),
                sim.components.map { it.instanceName }.sorted(),
            )
            sim.components.forEach { assertEquals(LifeCycleState.ACTIVE_STATE, it.state, it.instanceName) }
            assertEquals(listOf("sensors", "localisation"), sim.slaves.map { it.name })
            sim.killManager("sensors")
            assertEquals(
                listOf("laser_localise0", "map_client0", "planner0"),
                sim.components.map { it.instanceName }.sorted(),
            )
        }
    }

    @Test
    fun `slaves without a master run their components without a manager`() {
        val profile = saved.withExt(saved.ext.withProperties(saved.ext.properties - ProfileKeys.MANAGER))
        SimulatedSystem.start(profile).use { sim ->
            assertEquals(
                listOf(
                    "rtcoord.slave.1: no master manager (rtcoord.manager) for it to join: its components run without a manager",
                    "rtcoord.slave.2: no master manager (rtcoord.manager) for it to join: its components run without a manager",
                ),
                sim.warnings,
            )
            assertEquals(null, sim.manager)
            assertEquals(7, sim.components.size)
        }
    }

    private fun noPorts(type: String) =
        "type $type, which the manager can create, has no instance and no rtcoord.type.$type.port.PORT properties in the profile: its instances have no ports"

    private fun RtsProfile.withProperties(vararg properties: Pair<String, String>): RtsProfile =
        withExt(ext.withProperties(ext.properties + properties))
}
