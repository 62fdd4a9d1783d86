package org.rtcoord.sim

import RTC.LifeCycleState
import java.io.ByteArrayOutputStream
import java.io.PrintStream
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await
import org.rtcoord.profile.Extension
import org.rtcoord.runtime.DataType
import org.rtcoord.runtime.PortSpec
import org.rtcoord.runtime.RuntimeProcess

/** A system simulated from a profile saved from the fixtures' localisation system. */
class SimulatedSystemTest {
    private val profile = savedLocalisation()

    @Test
    fun `the saved components run with their ports, rates and connections, active, and data flows`() {
        SimulatedSystem.start(profile).use { sim ->
            assertEquals(
                listOf("laser0", "gyro0", "odometry0", "laser_localise0"),
                sim.components.map { it.instanceName },
            )
            sim.components.forEach { assertEquals(LifeCycleState.ACTIVE_STATE, it.state, it.instanceName) }
            val localiser = sim.component("laser_localise0")
            val ports = localiser.type.ports.associateBy { it.name }
            assertEquals(DataType.TIMED_DOUBLE_SEQ, (ports.getValue("laser") as PortSpec.DataIn).dataType)
            assertEquals(DataType.TIMED_DOUBLE_SEQ, (ports.getValue("pose") as PortSpec.DataOut).dataType)
            assertEquals(100.0, localiser.type.rate)
            assertEquals("0.5", localiser.type.configurationSets.getValue("precise")["gain"])
            assertEquals(listOf(RuntimeProcess.hostContext), localiser.contexts)
            await("the laser's data at the localiser") {
                localiser.latest("laser") != null && localiser.latest("odo") != null
            }
            // The slave can load odo_localise's module, but no instance in the profile tells its ports.
            assertEquals(
                listOf(
                    "type odo_localise, which the manager can create, has no instance and no rtcoord.type.odo_localise.port.PORT properties " +
                        "in the profile: its instances have no ports"
                ),
                sim.notes,
            )
            assertEquals(emptyList<String>(), sim.warnings, "the saved system is simulated whole")
        }
    }

    @Test
    fun `the manager creates the types the profile says it can, with the ports declared for them`() {
        val declared =
            profile.withExt(
                Extension(
                    properties =
                        profile.ext.properties +
                            mapOf(
                                ProfileKeys.MANAGER_TYPES to
                                    profile.ext.properties.getValue(ProfileKeys.MANAGER_TYPES) + ",odo_localise",
                                ProfileKeys.typePort("odo_localise", "odo") to "DataInPort IDL:RTC/TimedDoubleSeq:1.0",
                                ProfileKeys.typePort("odo_localise", "gyro") to "DataInPort RTC::TimedDouble",
                            )
                )
            )
        SimulatedSystem.start(declared).use { sim ->
            val manager = checkNotNull(sim.manager).ref
            assertEquals(
                "odo_localise0",
                manager.create_component("odo_localise").get_component_profile().instance_name,
            )
            val created = sim.component("odo_localise0")
            assertEquals(listOf("odo", "gyro"), created.type.ports.map { it.name })
        }
    }

    @Test
    fun `kill-manager leaves the components running and restart-naming keeps the bindings`() {
        SimulatedSystem.start(profile).use { sim ->
            val out = ByteArrayOutputStream()
            val err = ByteArrayOutputStream()
            val console = SimConsole(sim, PrintStream(out, true), PrintStream(err, true))
            console.execute("kill-manager")
            assertTrue(out.toString().startsWith("killed the manager"), out.toString())
            assertEquals(false, sim.hasLiveManager)
            console.execute("kill-manager")
            assertEquals("rtcoord sim: kill-manager: the manager manager.mgr was killed already\n", err.toString())
            val address = sim.address
            console.execute("restart-naming")
            assertEquals(address, sim.address)
            console.execute("break laser0")
            await("laser0 in ERROR") { sim.component("laser0").state == LifeCycleState.ERROR_STATE }
            assertEquals(LifeCycleState.ACTIVE_STATE, sim.component("gyro0").state)
        }
    }
}
