package org.rtcoord.runtime

import _SDOPackage.ConfigurationPOA
import _SDOPackage.ConfigurationSet
import _SDOPackage.DeviceProfile
import _SDOPackage.InternalError
import _SDOPackage.InvalidParameter
import _SDOPackage.NameValue
import _SDOPackage.NotAvailable
import _SDOPackage.Organization
import _SDOPackage.Parameter
import _SDOPackage.ServiceProfile
import org.omg.CORBA.Any
import org.omg.CORBA.ORB
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler

/**
 * A component's `SDOPackage::Configuration` with OpenRTM-aist's configuration-set semantics (`SdoConfiguration.py`,
 * `ConfigAdmin.py`): sets of string parameters (`default`, others, hidden `__name__` ones, each with exactly the values
 * it was given), the observer service profiles, and the component's bound variables.
 *
 * Writing a set's values, adding a set or removing one leaves the component with no active set until one is activated
 * (`get_active_configuration_set` raises `NotAvailable`); nothing is checked against the parameters' types then. Values
 * reach the variables only when the component runs ([update]: on activation, after each execution, in ERROR), and only
 * from an active set; a value a variable cannot take gives it its default. Changes raise the CONFIGURATION hints real
 * components send, in their real format (`UPDATE_CONFIG_PARAM: name.value`).
 */
internal class RuntimeConfiguration(
    private val orb: ORB,
    private val type: ComponentType,
    private val observers: ObserverHub,
    private val gate: Gate,
) : ConfigurationPOA() {
    private val lock = kotlin.Any()
    private val sets = LinkedHashMap<String, LinkedHashMap<String, String>>()

    /** The sets `add_configuration_set` made: the only ones `remove_configuration_set` removes. */
    private val added = HashSet<String>()
    private var activeId = "default"

    /** ConfigAdmin's `_active`: false from any change of the sets until a set is activated. */
    private var active = true

    /** ConfigAdmin's `_changed`: the variables are to be updated from the active set. */
    private var changed = false

    /** Each bound parameter's last applied string (OpenRTM's `string_value`): only a different one is applied. */
    private val applied = LinkedHashMap<String, String>()

    /** The bound variables, as the component's code sees them. */
    private val variables = LinkedHashMap<String, String>()

    init {
        sets["default"] = LinkedHashMap(type.parameters.associate { it.name to it.default })
        // A set holds the values it was given and no others, as ConfigAdmin's sets do: activating one
        // leaves the variables it does not name as they were.
        for ((id, values) in type.configurationSets) sets[id] = LinkedHashMap(values)
        type.parameters.forEach {
            applied[it.name] = it.default
            variables[it.name] = it.default
        }
    }

    /** The value of variable [name], as the component's code uses it. */
    fun parameter(name: String): String =
        parameterOrNull(name) ?: throw IllegalArgumentException("no parameter '$name'")

    /** The value of variable [name], or null when the component has no such parameter. */
    fun parameterOrNull(name: String): String? = synchronized(lock) { variables[name] }

    /** The active set's id, or null while no set is active. */
    val activeSet: String?
        get() = synchronized(lock) { activeId.takeIf { active } }

    /**
     * Applies the active set to the variables if a set was activated since the last update (ConfigAdmin `update()`),
     * announcing each variable given a new value, then the set.
     */
    fun update() {
        val hints =
            synchronized(lock) {
                if (!changed || !active) return
                changed = false
                val values = sets.getValue(activeId)
                val hints = mutableListOf<String>()
                for (spec in type.parameters) {
                    val value = values[spec.name] ?: continue
                    if (applied[spec.name] == value) continue
                    applied[spec.name] = value
                    variables[spec.name] = if (spec.accepts(value)) value else spec.default
                    hints += "UPDATE_CONFIG_PARAM: ${spec.name}.$value"
                }
                hints + "UPDATE_CONFIG_SET: $activeId"
            }
        hints.forEach { observers.raise(StatusKind.CONFIGURATION, it) }
    }

    override fun _invoke(method: String, input: InputStream, handler: ResponseHandler): OutputStream {
        gate.pass()
        return super._invoke(method, input, handler)
    }

    override fun get_configuration_sets(): Array<ConfigurationSet> =
        synchronized(lock) { sets.keys.map(::snapshot).toTypedArray() }

    override fun get_configuration_set(id: String?): ConfigurationSet =
        synchronized(lock) {
            if (id.isNullOrEmpty()) throw InvalidParameter("ID is empty")
            if (id !in sets) throw InternalError("No such ConfigurationSet")
            snapshot(id)
        }

    override fun get_active_configuration_set(): ConfigurationSet =
        synchronized(lock) {
            if (!active) throw NotAvailable("NotAvailable: Configuration.get_active_configuration_set()")
            snapshot(activeId)
        }

    override fun set_configuration_set_values(set: ConfigurationSet?): Boolean {
        val id = set?.id
        if (id.isNullOrEmpty()) throw InvalidParameter("ID is empty.")
        synchronized(lock) {
            val target = sets[id] ?: return false
            set.configuration_data.forEach { target[it.name] = it.stringValue() }
            changed = true
            active = false
        }
        observers.raise(StatusKind.CONFIGURATION, "SET_CONFIG_SET: $id")
        return true
    }

    override fun add_configuration_set(set: ConfigurationSet?): Boolean {
        if (set == null) throw InvalidParameter("configuration_set is empty.")
        synchronized(lock) {
            if (set.id.isNullOrEmpty() || set.id in sets) return false
            sets[set.id] = LinkedHashMap(set.configuration_data.associate { it.name to it.stringValue() })
            added += set.id
            changed = true
            active = false
        }
        observers.raise(StatusKind.CONFIGURATION, "ADD_CONFIG_SET: ${set.id}")
        return true
    }

    override fun remove_configuration_set(id: String?): Boolean {
        if (id.isNullOrEmpty()) throw InvalidParameter("ID is empty.")
        synchronized(lock) {
            // The active set's id counts even while no set is active, as in ConfigAdmin.
            if (id == "default" || id == activeId || id !in added) return false
            sets.remove(id)
            added -= id
            changed = true
            active = false
        }
        observers.raise(StatusKind.CONFIGURATION, "REMOVE_CONFIG_SET: $id")
        return true
    }

    override fun activate_configuration_set(id: String?): Boolean {
        if (id.isNullOrEmpty()) throw InvalidParameter("ID is empty.")
        synchronized(lock) {
            // Hidden `_name` sets cannot be activated.
            if (id.startsWith("_") || id !in sets) throw InternalError("Configuration.activate_configuration_set()")
            activeId = id
            active = true
            changed = true
        }
        observers.raise(StatusKind.CONFIGURATION, "ACTIVATE_CONFIG_SET: $id")
        return true
    }

    override fun add_service_profile(profile: ServiceProfile): Boolean = observers.add(profile)

    override fun remove_service_profile(id: String): Boolean = observers.remove(id)

    override fun set_device_profile(profile: DeviceProfile): Boolean = true

    override fun add_organization(member_of: Organization): Boolean = false

    override fun remove_organization(id: String): Boolean = false

    override fun get_configuration_parameters(): Array<Parameter> = emptyArray()

    override fun get_configuration_parameter_values(): Array<NameValue> = emptyArray()

    override fun get_configuration_parameter_value(name: String): Any =
        throw InvalidParameter("no SDO parameter '$name'")

    override fun set_configuration_parameter(name: String, value: Any): Boolean = false

    private fun snapshot(id: String): ConfigurationSet =
        ConfigurationSet(
            id,
            "",
            sets
                .getValue(id)
                .map { (name, value) -> NameValue(name, orb.create_any().apply { insert_string(value) }) }
                .toTypedArray(),
        )
}
