package org.rtcoord.sim

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.ReturnCode_t
import _SDOPackage.NameValue
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.RtsProfile
import org.rtcoord.runtime.RuntimeComponent

/**
 * Brings a simulated system's [processes] to what [profile] saved, as `rtcoord profile restore` and rtshell's `rtstart`
 * leave a system: each component created in the process its manager was given, bound at its path, its active
 * configuration set as saved (none, if none was), then every connection made with its properties and every component
 * activated in each context it owns. A step that fails is named in [warnings] and the others are taken all the same.
 */
internal class SimulatedStart(
    private val profile: RtsProfile,
    private val types: SimulatedTypes,
    private val processes: SimulatedProcesses,
    private val warnings: MutableList<String>,
) {
    private val created = linkedMapOf<String, RuntimeComponent>()

    fun run() {
        for (component in profile.components) {
            val type = types.byInstance[component.instanceName] ?: continue
            val process = processes.processFor(component.instanceName)
            val runtime =
                process.create(
                    type,
                    component.instanceName,
                    contexts = ManagerTopology.namingPath(component.pathUri).dropLast(1),
                )
            created[component.instanceName] = runtime
            configure(component, runtime)
        }
        (profile.dataPortConnectors - types.mismatchedConnectors + profile.servicePortConnectors).forEach(::connect)
        for ((name, component) in created) {
            val result = component.activateEverywhere()
            if (result != ReturnCode_t.RTC_OK)
                warnings += "component $name: activating it answered ${result.value()}: left inactive"
        }
    }

    /**
     * Activates the saved active set; a component saved with no set active is left with none, as OpenRTM-aist leaves it
     * after a write.
     */
    private fun configure(saved: ProfileComponent, runtime: RuntimeComponent) {
        val configuration = runtime.ref.get_configuration()
        val set = saved.activeConfigurationSet
        when {
            set.isEmpty() ->
                configuration
                    .get_configuration_sets()
                    .firstOrNull { it.id == "default" }
                    ?.let { configuration.set_configuration_set_values(it) }
            set == "default" -> Unit
            !runCatching { configuration.activate_configuration_set(set) }.getOrDefault(false) ->
                warnings +=
                    "component ${saved.instanceName}: configuration set '$set' cannot be activated (no such set, or a hidden one): 'default' is active"
        }
    }

    /** Connects [connector]'s ports through the first one's `connect`, as rtshell's `rtcon` and `rtresurrect` do. */
    private fun connect(connector: PortConnector) {
        val where = "connector ${connector.name}"
        val ports =
            listOf(connector.source, connector.target).map { end ->
                val component = created[end.instanceName]
                val port = component?.ref?.get_ports()?.firstOrNull { it.get_port_profile().name == end.portName }
                if (port == null) {
                    warnings +=
                        "$where: " +
                            (if (component == null) "no component ${end.instanceName} simulated"
                            else "${end.instanceName} has no port ${end.portName}") +
                            ": left out"
                    return
                }
                port
            }
        val orb = processes.processFor(connector.source.instanceName).orb.orb
        val properties =
            connector.connectionProperties().map { (key, value) ->
                NameValue(key, orb.create_any().apply { insert_string(value) })
            }
        val holder =
            ConnectorProfileHolder(
                ConnectorProfile(connector.name, connector.connectorId, ports.toTypedArray(), properties.toTypedArray())
            )
        val result = ports[0].connect(holder)
        if (result != ReturnCode_t.RTC_OK) {
            warnings +=
                "$where (${connector.source.portName} to ${connector.target.portName}): connect answered ${result.value()}: left out"
        }
    }
}
