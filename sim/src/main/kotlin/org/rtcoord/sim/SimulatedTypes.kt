package org.rtcoord.sim

import org.rtcoord.datatypes.IdlDefinitions
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfilePort
import org.rtcoord.profile.RtsProfile
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.DataType
import org.rtcoord.runtime.PortSpec

/**
 * The component types a profile describes: one per component in it (its ports, configuration sets and execution
 * contexts) and one per type its managers can create ([ProfileKeys.MANAGER_TYPES] and each slave's), whose ports come
 * from [ProfileKeys.typePort] properties or else from an instance of the type in the profile. A data port's type is one
 * of OpenRTM-aist's standard data types or one the user's IDL declares ([userTypes]); a port of any other type is kept,
 * connectable, and sends nothing (a warning says so once). A component whose type cannot be built is left out and named
 * in [warnings].
 */
internal class SimulatedTypes(private val profile: RtsProfile, private val userTypes: IdlDefinitions? = null) {
    /** What could not be simulated as the profile says, one line each; first the IDL that could not be read. */
    val warnings = userTypes?.errors.orEmpty().toMutableList()

    /** What the profile cannot tell, one line each: the types the managers can create whose ports are not known. */
    val notes = mutableListOf<String>()

    /** The type of each component that can be simulated, by instance name. */
    val byInstance: Map<String, ComponentType> =
        profile.components
            .mapNotNull { component ->
                try {
                    component.instanceName to componentType(component)
                } catch (e: IllegalArgumentException) {
                    warnings += "component ${component.instanceName}: ${e.message}: left out"
                    null
                }
            }
            .toMap()

    /** The types the manager can create, by type name: those listed, and those of the profile's components. */
    val creatable: Map<String, ComponentType> = buildMap {
        byInstance.values.forEach { put(it.typeName, it) }
        for (typeName in managerTypes()) {
            if (typeName !in this || declaredPorts(typeName).isNotEmpty()) put(typeName, declaredType(typeName))
        }
    }

    /**
     * The data connectors left out because their ports carry different data types, which OpenRTM-aist refuses to
     * connect; each is a warning naming the connector and both types.
     */
    val mismatchedConnectors: Set<PortConnector> =
        profile.dataPortConnectors
            .filter { connector ->
                val types =
                    listOf(connector.source, connector.target).map { end ->
                        byInstance[end.instanceName]
                            ?.ports
                            ?.firstOrNull { "${end.instanceName}.${it.name}" == end.portName }
                            ?.let(::dataTypeOf)
                    }
                val mismatched = types.none { it == null } && types[0] != types[1]
                if (mismatched) {
                    warn(
                        "connector ${connector.name} (${connector.source.portName} to ${connector.target.portName}): left out: " +
                            "it joins ${types[0]} to ${types[1]}, which OpenRTM-aist refuses to connect"
                    )
                }
                mismatched
            }
            .toSet()

    private fun dataTypeOf(port: PortSpec): DataType? =
        when (port) {
            is PortSpec.DataIn -> port.dataType
            is PortSpec.DataOut -> port.dataType
            is PortSpec.Service -> null
        }

    /** The types the master and each slave can create, as the profile lists them. */
    private fun managerTypes(): List<String> {
        val slaves =
            profile.ext.properties.filterKeys {
                it.startsWith(ProfileKeys.SLAVE_PREFIX) && (it.endsWith(".types") || it.endsWith(".loadable"))
            }
        return (listOfNotNull(profile.ext.properties[ProfileKeys.MANAGER_TYPES]) + slaves.values)
            .flatMap { it.split(',') }
            .map { it.trim() }
            .filter { it.isNotEmpty() }
            .distinct()
    }

    private fun componentType(component: ProfileComponent): ComponentType {
        val id = component.id.split(':')
        val typeName = id.getOrNull(3)?.takeIf { it.isNotBlank() } ?: component.instanceName
        val declared = declaredPorts(typeName)
        val ports = declared.ifEmpty {
            component.dataPorts.mapNotNull { dataPort(component, it) } +
                component.servicePorts.map { servicePort(it, "${component.instanceName}.${it.name}", warnings) }
        }
        val configuration = SimulatedConfiguration(component)
        return ComponentType(
            typeName,
            ports = ports,
            parameters = configuration.parameters,
            configurationSets = configuration.sets,
            behaviour = { SimulatedBehaviour(ports) },
            contexts = SimulatedContexts(component, warnings).specs,
            vendor = id.getOrNull(1).orEmpty(),
            category = id.getOrNull(2).orEmpty(),
            version = id.getOrNull(4).orEmpty(),
            description = "simulated from ${component.instanceName} in ${profile.id}",
        )
    }

    /** A type known only by name: its ports from the profile's properties, or an instance of it elsewhere. */
    private fun declaredType(typeName: String): ComponentType {
        val ports = declaredPorts(typeName)
        if (ports.isEmpty()) {
            notes +=
                "type $typeName, which the manager can create, has no instance and no ${ProfileKeys.typePort(typeName, "PORT")} " +
                    "properties in the profile: its instances have no ports"
        }
        return ComponentType(
            typeName,
            ports = ports,
            behaviour = { SimulatedBehaviour(ports) },
            description = "simulated $typeName",
        )
    }

    private fun declaredPorts(typeName: String): List<PortSpec> {
        val prefix = ProfileKeys.typePort(typeName, "")
        return profile.ext.properties
            .filterKeys { it.startsWith(prefix) }
            .map { (key, value) ->
                val name = key.removePrefix(prefix)
                val words = value.trim().split(Regex("\\s+"))
                portSpec(name, words[0], words.getOrNull(1)) { "$key: $it" }
                    ?: throw IllegalArgumentException(
                        "$key: '$value' is not 'DataInPort TYPE', 'DataOutPort TYPE' or 'CorbaPort'"
                    )
            }
    }

    /**
     * A data port as its properties say (`port.port_type`, `dataport.data_type`, as RTSystemEditor and `rtcoord profile
     * save` write them), else as the profile's connectors use it: the source of a data connector is an out-port, its
     * target an in-port.
     */
    private fun dataPort(component: ProfileComponent, port: ProfilePort): PortSpec? {
        val fullName = "${component.instanceName}.${port.name}"
        val connectors = profile.dataPortConnectors
        val asSource = connectors.firstOrNull {
            it.source.instanceName == component.instanceName && it.source.portName == fullName
        }
        val asTarget = connectors.firstOrNull {
            it.target.instanceName == component.instanceName && it.target.portName == fullName
        }
        val kind =
            port.ext.properties["port.port_type"]
                ?: when {
                    asSource != null -> "DataOutPort"
                    asTarget != null -> "DataInPort"
                    else -> null
                }
        val dataType = port.ext.properties["dataport.data_type"] ?: (asSource ?: asTarget)?.dataType
        if (kind == null) {
            warnings += "$fullName: left out: the profile says neither its kind (port.port_type) nor a connection of it"
            return null
        }
        return portSpec(port.name, kind, dataType) { "$fullName: $it" }
    }

    private fun portSpec(name: String, kind: String, dataType: String?, where: (String) -> String): PortSpec? =
        when (kind) {
            "CorbaPort" -> PortSpec.Service(name)
            "DataInPort",
            "DataOutPort" ->
                if (dataType.isNullOrBlank()) {
                    warn(where("left out: the profile gives no data type (dataport.data_type)"))
                    null
                } else {
                    val type = dataType(dataType, sends = kind == "DataOutPort", where)
                    if (kind == "DataInPort") PortSpec.DataIn(name, type) else PortSpec.DataOut(name, type)
                }
            else -> null
        }

    /**
     * The type [name] means: the user's IDL first (`IDL:RTC/TimedDouble:1.0`, `RTC::TimedDouble` and `TimedDouble` all
     * name one type), then OpenRTM-aist's standard types; else a type with no IDL, whose out-ports send nothing.
     */
    private fun dataType(name: String, sends: Boolean, where: (String) -> String): DataType {
        userTypes?.named(name)?.let {
            return DataType(name, it)
        }
        DataType.of(name)?.let {
            return it
        }
        if (sends)
            warn(
                where(
                    "sends no data: its data type $name is not one of OpenRTM-aist's and no IDL given declares it " +
                        "(give the directory of its IDL: rtcoord sim --idl DIR, or idl(\"DIR\") in a test)"
                )
            )
        return DataType(name, null)
    }

    /** Adds [line] to [warnings] once: a type's ports are read for each instance and for its manager. */
    private fun warn(line: String) {
        if (line !in warnings) warnings += line
    }
}
