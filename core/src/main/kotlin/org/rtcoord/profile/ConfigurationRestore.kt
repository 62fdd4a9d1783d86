package org.rtcoord.profile

import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.internal.ParameterConstraint

/**
 * Every configuration call a restore makes, in one place. Values are written set by set and the
 * profile's active set is then activated explicitly: OpenRTM applies a set's values to the component's
 * variables only on activation (`activate_configuration_set`), whatever was active before.
 */
internal object ConfigurationRestore {
    /**
     * The sets a restore writes: hidden ones (`__constraints__`, which rtcryo saves too) describe the
     * parameters and are not written.
     */
    fun restorable(wanted: ProfileComponent): List<ConfigurationSet> = wanted.configurationSets.filter { !SystemCapture.isHidden(it.id) }

    /** Why [wanted] cannot be written to the component with [live] configuration, or null if it can. */
    fun problem(wanted: ProfileComponent, live: ConfigurationSnapshot): String? {
        val constraints = live.sets["__constraints__"].orEmpty()
        for (set in restorable(wanted)) {
            val current = live.sets[set.id]
            for ((name, value) in set.data) {
                if (current != null && name !in current) return "no parameter '$name' in configuration set '${set.id}'"
                val constraint = constraints[name] ?: continue
                ParameterConstraint.violation(constraint, value)?.let { return "configuration set '${set.id}': $it" }
            }
        }
        val active = wanted.activeConfigurationSet
        if (active.isNotEmpty() && active !in live.sets && wanted.configurationSet(active) == null) {
            return "no configuration set '$active' to activate"
        }
        return null
    }

    /** Writes what differs and activates the profile's set; returns what it did, empty when nothing differed. */
    suspend fun apply(node: ComponentNode, wanted: ProfileComponent): List<String> {
        val live = node.configuration()
        val done = mutableListOf<String>()
        var activeChanged = false
        for (set in restorable(wanted)) {
            val current = live.sets[set.id]
            when {
                current == null -> {
                    node.addConfigurationSet(set.id, set.data)
                    done += "added configuration set '${set.id}'"
                }
                else -> {
                    val changed = set.data.filter { (name, value) -> current[name] != value }
                    if (changed.isEmpty()) continue
                    node.setParameters(changed, set.id)
                    done += "set ${changed.keys.joinToString()} in '${set.id}'"
                }
            }
            if (set.id == wanted.activeConfigurationSet) activeChanged = true
        }
        val active = wanted.activeConfigurationSet
        if (active.isNotEmpty() && (activeChanged || live.activeSet != active)) {
            node.activateConfigurationSet(active)
            done += "activated configuration set '$active'"
        }
        return done
    }
}
