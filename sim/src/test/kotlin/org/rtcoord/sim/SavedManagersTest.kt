package org.rtcoord.sim

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.omg.CosNaming.NamingContextExtHelper
import org.rtcoord.runtime.RuntimeOrb
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.sim.test.Faults
import org.rtcoord.sim.test.SimFaults

/** A system saved with its managers is simulated with them: one process per slave, as far as faults go. */
class SavedManagersTest {
    @Test
    fun `profile save records the master, each slave, what each hosts and can create`() {
        val saved = TwoSlaveSystem.start().use { it.save() }.ext.properties
        assertEquals(
            "${RuntimeProcess.hostContext}/manager.mgr",
            saved.getValue(ProfileKeys.MANAGER).substringAfter('/'),
        )
        val slaves = saved.filterKeys { it.startsWith(ProfileKeys.SLAVE_PREFIX) }
        assertEquals(
            mapOf(
                "rtcoord.slave.1.name" to "sensors",
                "rtcoord.slave.1.components" to "laser0,gyro0,odometry0,map_server0",
                "rtcoord.slave.1.types" to "laser,gyro,odometry,map_server",
                "rtcoord.slave.1.loadable" to "",
                "rtcoord.slave.2.name" to "localisation",
                "rtcoord.slave.2.components" to "laser_localise0,map_client0,planner0",
                "rtcoord.slave.2.types" to "laser_localise,map_client,planner",
                "rtcoord.slave.2.loadable" to "odo_localise",
            ),
            slaves,
        )
        assertEquals(
            "laser,gyro,odometry,map_server,laser_localise,map_client,planner,odo_localise",
            saved[ProfileKeys.MANAGER_TYPES],
        )
        assertNull(saved[ProfileKeys.MANAGER_COMPONENTS], "the master hosts nothing itself")
    }

    @Test
    fun `killing a slave takes exactly its components, and the master drops it at its first call that fails`() {
        val profile = TwoSlaveSystem.start().use { it.save() }
        SimulatedSystem.start(profile).use { sim ->
            assertEquals(listOf("sensors", "localisation"), sim.slaves.map { it.name })
            val master = checkNotNull(sim.manager).ref
            // As a test's `at(...) { killManager("localisation") }` does it.
            val faults: Faults = SimFaults(sim) {}
            faults.killManager("localisation")

            assertEquals(listOf("laser0", "gyro0", "odometry0", "map_server0"), sim.components.map { it.instanceName })
            assertEquals(
                2,
                master.get_slave_managers().size,
                "the master lists the dead slave until a call to it fails",
            )
            val hosted = master.get_components().map { it.get_component_profile().instance_name }
            assertEquals(listOf("laser0", "gyro0", "odometry0", "map_server0"), hosted)
            assertEquals(1, master.get_slave_managers().size, "get_components failed on the dead slave: dropped")

            RuntimeOrb.start().use { orb ->
                val naming = NamingContextExtHelper.narrow(orb.orb.string_to_object(sim.corbaloc))
                val dead = naming.resolve_str("${RuntimeProcess.hostContext}/laser_localise0.rtc")
                assertThrows<org.omg.CORBA.SystemException> { dead._non_existent() }
            }
            val again = assertThrows<IllegalStateException> { sim.killManager("manager.mgr/localisation") }
            assertEquals("the manager manager.mgr/localisation was killed already", again.message)
            assertEquals(
                "no manager mapping in the simulated system (managers: manager.mgr, manager.mgr/sensors, manager.mgr/localisation)",
                assertThrows<IllegalArgumentException> { sim.killManager("mapping") }.message,
            )
            assertTrue(sim.hasLiveManager)
        }
    }

    @Test
    fun `a master whose profile records a command starts a slave for a type no live slave can create`() {
        val saved = TwoSlaveSystem.start().use { it.save() }
        val profile =
            saved.withExt(
                saved.ext.withProperties(saved.ext.properties + (ProfileKeys.MANAGER_COMMAND to "rtcd_python"))
            )
        SimulatedSystem.start(profile).use { sim ->
            sim.killManager("localisation")
            val created = checkNotNull(sim.manager).ref.create_component("laser_localise")
            assertEquals("laser_localise0", created.get_component_profile().instance_name)
            assertEquals(3, sim.slaves.size, "a slave started for it")
            assertEquals(listOf("laser_localise0"), sim.slaves.last().runtime.components.map { it.instanceName })
        }
    }

    @Test
    fun `a profile that records a master but no slave still simulates with one slave hosting everything`() {
        val saved = TwoSlaveSystem.start().use { it.save() }
        val old =
            saved.withExt(
                saved.ext.withProperties(saved.ext.properties.filterKeys { !it.startsWith(ProfileKeys.SLAVE_PREFIX) })
            )
        SimulatedSystem.start(old).use { sim ->
            assertEquals(listOf(ManagerTopology.DEFAULT_SLAVE), sim.slaves.map { it.name })
            assertEquals(7, sim.slaves.single().runtime.components.size)
            assertTrue(sim.warnings.none { "slave" in it }, sim.warnings.toString())
        }
    }
}
