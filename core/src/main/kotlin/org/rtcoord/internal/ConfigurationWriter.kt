package org.rtcoord.internal

import RTC.RTObject
import _SDOPackage.Configuration
import _SDOPackage.ConfigurationSet
import _SDOPackage.NameValue
import _SDOPackage.NotAvailable
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import org.omg.CORBA.ORB
import org.rtcoord.BadParameterException
import org.rtcoord.NotFoundException
import org.rtcoord.OperationFailedException
import org.rtcoord.PreconditionNotMetException

/**
 * Changes a component's configuration sets so that the change takes effect. OpenRTM-aist's ConfigAdmin leaves a
 * component with no active set after every write (set values, add a set, remove one), and its variables take values
 * only from a set activated since: so each write here is followed by activating the set that was active (the written
 * one when none was, for values), and read back: the values written, and that a set is active.
 */
internal class ConfigurationWriter(
    private val remote: Remote,
    private val orb: ORB,
    private val subject: String,
    private val component: RTObject,
) {

    /**
     * Writes [values] into set [set] (the active one when null), checked first against the set's parameters and the
     * `__constraints__` the component declares, then activates the set that was active, or [set] when none was, and
     * reads the values back. A value outside its constraint is written, as OpenRTM-aist writes it, and returned as a
     * warning (`gain: '42' is outside 0<x<10`); [strict] refuses it instead.
     */
    suspend fun setValues(values: Map<String, String>, set: String?, strict: Boolean): List<String> {
        require(values.isNotEmpty()) { "no parameters to set" }
        val operation = "set ${values.keys.joinToString()}"
        val (configuration, sets, active) = read()
        val target =
            set
                ?: active
                ?: throw PreconditionNotMetException(
                    subject,
                    operation,
                    "no configuration set is active: name the set to change (sets: ${sets.ids()})",
                )
        val current = sets.firstOrNull { it.id == target } ?: throw noSuchSet(target, sets)
        val parameters = current.configuration_data.map { it.name }
        values.keys
            .firstOrNull { it !in parameters }
            ?.let { missing ->
                throw NotFoundException(
                    subject,
                    "no parameter '$missing' in configuration set '$target' (parameters: ${parameters.sorted().joinToString()})",
                )
            }
        val constraints = sets.firstOrNull { it.id == ParameterConstraint.SET }?.configuration_data?.toMap().orEmpty()
        val violations = ParameterConstraint.violations(values, current.configuration_data.toMap(), constraints)
        if (strict)
            violations.entries.firstOrNull()?.let { (name, why) ->
                throw BadParameterException(subject, "set $name", why)
            }
        // Only the changed values: the component merges them into the set, leaving the others as they are now.
        val changes =
            values
                .map { (name, value) -> NameValue(name, orb.create_any().apply { insert_string(value) }) }
                .toTypedArray()
        val accepted =
            remote.call(subject, operation) {
                configuration.set_configuration_set_values(ConfigurationSet(target, current.description, changes))
            }
        if (!accepted) throw BadParameterException(subject, operation, "refused in set '$target'")
        activate(configuration, active ?: target, operation)
        val stored =
            remote
                .call(subject, "get_configuration_set") { configuration.get_configuration_set(target) }
                .configuration_data
                .toMap()
        val lost = values.filter { (name, value) -> stored[name] != value }
        if (lost.isNotEmpty()) {
            throw OperationFailedException(
                subject,
                operation,
                "read back",
                "set '$target' holds ${lost.keys.joinToString { "$it=${stored[it]}" }}",
            )
        }
        return violations.map { (name, why) -> "$name: $why" }
    }

    /** Makes set [id] the active one; checks that a set is active then. */
    suspend fun activate(id: String) {
        val operation = "activate configuration set '$id'"
        val (configuration, sets, _) = read()
        if (sets.none { it.id == id }) throw noSuchSet(id, sets)
        // OpenRTM answers only InternalError for these.
        if (id.startsWith("_")) throw BadParameterException(subject, operation, "a hidden set cannot be activated")
        activate(configuration, id, operation)
    }

    /** Adds set [id] holding [values], keeping the active set active. */
    suspend fun add(id: String, values: Map<String, String>) {
        val operation = "add configuration set '$id'"
        val (configuration, sets, active) = read()
        if (sets.any { it.id == id }) throw BadParameterException(subject, operation, "the component has a set '$id'")
        val data =
            values
                .map { (name, value) -> NameValue(name, orb.create_any().apply { insert_string(value) }) }
                .toTypedArray()
        if (!remote.call(subject, operation) { configuration.add_configuration_set(ConfigurationSet(id, "", data)) }) {
            throw BadParameterException(subject, operation, "refused")
        }
        active?.let { activate(configuration, it, operation) }
    }

    /** Removes set [id], keeping the active set active. */
    suspend fun remove(id: String) {
        val operation = "remove configuration set '$id'"
        val (configuration, sets, active) = read()
        if (sets.none { it.id == id }) throw noSuchSet(id, sets)
        if (!remote.call(subject, operation) { configuration.remove_configuration_set(id) }) {
            throw BadParameterException(
                subject,
                operation,
                "refused: only a set added at run time can be removed, and not while it is the active one",
            )
        }
        active?.let { activate(configuration, it, operation) }
    }

    /** The configuration object, its sets and the active set's id (null: none is active). */
    private suspend fun read(): Triple<Configuration, List<ConfigurationSet>, String?> {
        val configuration = remote.call(subject, "get_configuration") { component.get_configuration() }
        return coroutineScope {
            val sets = async {
                remote.call(subject, "get_configuration_sets") { configuration.get_configuration_sets().toList() }
            }
            val active = async { remote.call(subject, "get_active_configuration_set") { configuration.activeSetId() } }
            Triple(configuration, sets.await(), active.await())
        }
    }

    private suspend fun activate(configuration: Configuration, id: String, operation: String) {
        if (
            !remote.call(subject, "activate configuration set '$id'") { configuration.activate_configuration_set(id) }
        ) {
            throw OperationFailedException(subject, operation, "false", "activating set '$id'")
        }
        // Another client may have activated a set since, which is its right; none active means nothing takes effect.
        remote.call(subject, "get_active_configuration_set") { configuration.activeSetId() }
            ?: throw OperationFailedException(
                subject,
                operation,
                "read back",
                "no configuration set is active after activating '$id'",
            )
    }

    private fun noSuchSet(id: String, sets: List<ConfigurationSet>) =
        NotFoundException(subject, "no configuration set '$id' (sets: ${sets.ids()})")

    private fun List<ConfigurationSet>.ids(): String = map { it.id }.sorted().joinToString()
}

/**
 * The active configuration set's id, or null while the component has none (OpenRTM-aist, after a set was written, added
 * or removed).
 */
internal fun Configuration.activeSetId(): String? =
    try {
        get_active_configuration_set().id
    } catch (e: NotAvailable) {
        null
    }
