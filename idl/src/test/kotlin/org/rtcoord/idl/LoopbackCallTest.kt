package org.rtcoord.idl

import RTC.ExecutionContextProfile
import RTC.ExecutionContextServiceHelper
import RTC.ExecutionContextServicePOA
import RTC.ExecutionKind
import RTC.LifeCycleState
import RTC.LightweightRTObject
import RTC.ReturnCode_t
import _SDOPackage.ConfigurationHelper
import _SDOPackage.ConfigurationPOA
import _SDOPackage.ConfigurationSet
import _SDOPackage.InvalidParameter
import _SDOPackage.NameValue
import _SDOPackage.Organization
import _SDOPackage.ServiceProfile
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CORBA.Any

/**
 * The generated bindings work on JacORB over real IIOP: the servant lives in one ORB, the client in another, so every
 * call is marshalled and sent over loopback.
 */
class LoopbackCallTest {
    private class RateContext : ExecutionContextServicePOA() {
        var rate = 1000.0

        override fun get_profile() =
            ExecutionContextProfile(ExecutionKind.PERIODIC, rate, null, emptyArray(), emptyArray())

        override fun is_running() = true

        override fun start() = ReturnCode_t.PRECONDITION_NOT_MET

        override fun stop() = ReturnCode_t.RTC_OK

        override fun get_rate() = rate

        override fun set_rate(rate: Double): ReturnCode_t {
            if (rate <= 0.0) return ReturnCode_t.BAD_PARAMETER
            this.rate = rate
            return ReturnCode_t.RTC_OK
        }

        override fun add_component(comp: LightweightRTObject?) = ReturnCode_t.RTC_OK

        override fun remove_component(comp: LightweightRTObject?) = ReturnCode_t.RTC_OK

        override fun activate_component(comp: LightweightRTObject?) = ReturnCode_t.RTC_OK

        override fun deactivate_component(comp: LightweightRTObject?) = ReturnCode_t.RTC_OK

        override fun reset_component(comp: LightweightRTObject?) = ReturnCode_t.RTC_OK

        override fun get_component_state(comp: LightweightRTObject?) = LifeCycleState.INACTIVE_STATE

        override fun get_kind() = ExecutionKind.PERIODIC
    }

    /** Rejects every set: enough to see a user exception of the SDO module cross the wire. */
    private class RejectingConfiguration : ConfigurationPOA() {
        private fun reject(what: String): Nothing = throw InvalidParameter("no $what here")

        override fun set_device_profile(profile: _SDOPackage.DeviceProfile?) = reject("device profile")

        override fun add_service_profile(profile: ServiceProfile?) = reject("service")

        override fun add_organization(member_of: Organization?) = reject("organization")

        override fun remove_service_profile(id: String?) = reject("service $id")

        override fun remove_organization(id: String?) = reject("organization $id")

        override fun get_configuration_parameters() = emptyArray<_SDOPackage.Parameter>()

        override fun get_configuration_parameter_values() = emptyArray<NameValue>()

        override fun get_configuration_parameter_value(name: String?): Any = reject("parameter $name")

        override fun set_configuration_parameter(name: String?, value: Any?) = reject("parameter $name")

        override fun get_configuration_sets() = emptyArray<ConfigurationSet>()

        override fun get_configuration_set(id: String?) = reject("set $id")

        override fun set_configuration_set_values(set: ConfigurationSet?) = reject("set ${set?.id}")

        override fun get_active_configuration_set() = ConfigurationSet("default", "", emptyArray())

        override fun add_configuration_set(set: ConfigurationSet?) = reject("set ${set?.id}")

        override fun remove_configuration_set(id: String?) = reject("set $id")

        override fun activate_configuration_set(id: String?) = reject("set $id")
    }

    @Test
    fun `an execution context servant answers over loopback IIOP`() {
        LoopbackOrb().use { server ->
            LoopbackOrb().use { client ->
                val servant = RateContext()
                val ior = server.orb.object_to_string(server.poa.servant_to_reference(servant))
                assertTrue(ior.startsWith("IOR:"))

                val context = ExecutionContextServiceHelper.narrow(client.orb.string_to_object(ior))
                assertTrue(context._is_a("IDL:omg.org/RTC/ExecutionContext:1.0"))
                assertEquals(ReturnCode_t.RTC_OK, context.set_rate(25.0))
                assertEquals(ReturnCode_t.BAD_PARAMETER, context.set_rate(-1.0))
                assertEquals(25.0, context.get_rate())
                assertEquals(25.0, context.get_profile().rate)
                assertEquals(25.0, servant.rate)
            }
        }
    }

    @Test
    fun `an SDO user exception arrives as its own type`() {
        LoopbackOrb().use { server ->
            LoopbackOrb().use { client ->
                val ior = server.orb.object_to_string(server.poa.servant_to_reference(RejectingConfiguration()))
                val configuration = ConfigurationHelper.narrow(client.orb.string_to_object(ior))

                val error =
                    assertThrows(InvalidParameter::class.java) { configuration.activate_configuration_set("fast") }
                assertEquals("no set fast here", error.description)
                assertEquals("default", configuration.get_active_configuration_set().id)
            }
        }
    }
}
