package org.rtcoord.sim

import RTC.ExecutionKind
import _SDOPackage.ConfigurationSet
import _SDOPackage.NameValue
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.omg.CORBA.NO_IMPLEMENT
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.RuntimeOrb

/** Service ports, execution contexts and configuration, simulated as a profile saved them. */
class SavedComponentsTest {
    private val profile = TwoSlaveSystem.start().use { it.save() }

    @Test
    fun `a service port has its saved interfaces, and a call on a provided one fails at once with NO_IMPLEMENT`() {
        SimulatedSystem.start(profile).use { sim ->
            val server = sim.component("map_server0").ref.get_ports().single().get_port_profile()
            assertEquals(
                listOf("map MapServer::Map PROVIDED", "pose Localisation::PoseSource REQUIRED"),
                server.interfaces.map {
                    "${it.instance_name} ${it.type_name} ${if (it.polarity == RTC.PortInterfacePolarity.PROVIDED) "PROVIDED" else "REQUIRED"}"
                },
            )
            val client = sim.component("map_client0").ref.get_ports().single()
            val connector = client.get_connector_profiles().single()
            val properties = connector.properties.associate { it.name to it.value.extract_string() }
            val ior = properties.getValue("port.MapServer::Map.map")
            assertEquals(ior, properties["map_server0.port.map.provided.MapServer::Map.map"])

            RuntimeOrb.start().use { orb ->
                val map = orb.orb.string_to_object(ior)
                assertTrue(map._is_a("IDL:MapServer/Map:1.0"))
                val started = TimeSource.Monotonic.markNow()
                val request =
                    map._request("get_map").apply {
                        set_return_type(orb.orb.get_primitive_tc(org.omg.CORBA.TCKind.tk_string))
                    }
                val refused =
                    assertThrows<NO_IMPLEMENT> {
                        request.invoke()
                        request.env().exception()?.let { throw it }
                    }
                assertTrue(started.elapsedNow() < 2.seconds, "answered in ${started.elapsedNow()}")
                // JacORB reads the message from the reply's ExceptionDetailMessage, after a prefix of its own.
                val expected =
                    "map_server0.map: interface map (MapServer::Map) is simulated without an implementation: get_map cannot be answered " +
                        "(rtcoord simulates service ports, not their operations)"
                assertTrue(refused.message.orEmpty().endsWith(expected), refused.message)
            }
            assertEquals(RTC.ReturnCode_t.RTC_OK, client.disconnect(connector.connector_id))
            assertTrue(sim.component("map_server0").ref.get_ports().single().get_connector_profiles().isEmpty())
        }
    }

    @Test
    fun `every execution context is simulated with its kind, rate and implementation`() {
        SimulatedSystem.start(profile).use { sim ->
            val planner = sim.component("planner0").ref
            val contexts =
                planner.get_owned_contexts().map { RTC.ExecutionContextServiceHelper.narrow(it).get_profile() }
            assertEquals(
                listOf(ExecutionKind.PERIODIC to 20.0, ExecutionKind.EVENT_DRIVEN to 5.0),
                contexts.map { it.kind to it.rate },
            )
            assertEquals(
                listOf("PeriodicExecutionContext", "EventDrivenExecutionContext"),
                contexts.map { profile -> profile.properties.single { it.name == "type" }.value.extract_string() },
            )
            assertEquals(1, planner.get_context_handle(planner.get_owned_contexts()[1]))
            sim.components.forEach { component ->
                val handles = component.ref.get_owned_contexts().indices
                assertTrue(
                    handles.all {
                        component.ref.get_context(it).get_component_state(component.ref) ==
                            RTC.LifeCycleState.ACTIVE_STATE
                    },
                    component.instanceName,
                )
            }
        }
    }

    @Test
    fun `every configuration set is simulated with exactly its values, hidden ones too, and a constrained number stays a number`() {
        SimulatedSystem.start(profile).use { sim ->
            val planner = sim.component("planner0")
            val configuration = planner.ref.get_configuration()
            val sets =
                configuration.get_configuration_sets().associate { set ->
                    set.id to set.configuration_data.associate { it.name to it.value.extract_string() }
                }
            assertEquals(
                mapOf(
                    "__constraints__" to mapOf("horizon" to "0<=x<=100", "mode" to "(safe,fast)"),
                    "__widget__" to mapOf("horizon" to "slider.1", "mode" to "radio"),
                    "default" to mapOf("horizon" to "10", "mode" to "safe"),
                    "fast" to mapOf("horizon" to "3"),
                ),
                sets.toSortedMap(),
            )
            assertEquals("default", planner.activeConfigurationSet)

            // OpenRTM-aist stores values outside a constraint; a numeric variable cannot take a word.
            RuntimeOrb.start().use { orb ->
                fun write(values: Map<String, String>) {
                    val data = values.map { (name, value) ->
                        NameValue(name, orb.orb.create_any().apply { insert_string(value) })
                    }
                    configuration.set_configuration_set_values(ConfigurationSet("fast", "", data.toTypedArray()))
                    configuration.activate_configuration_set("fast")
                }
                write(mapOf("horizon" to "250", "mode" to "reckless"))
                await("the active set's values in the variables") {
                    planner.parameter("horizon") == "250" && planner.parameter("mode") == "reckless"
                }
                write(mapOf("horizon" to "many"))
                await("a word to give the numeric variable its default") { planner.parameter("horizon") == "10" }
            }
        }
    }
}
