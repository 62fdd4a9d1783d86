package org.rtcoord.profile.internal

import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.internal.ParameterConstraint
import org.rtcoord.profile.ConfigurationSet
import org.rtcoord.profile.ProfileComponent

/**
 * Every configuration call a restore makes, in one place. Values are written set by set and the profile's active set is
 * then activated explicitly: OpenRTM applies a set's values to the component's variables only on activation
 * (`activate_configuration_set`), whatever was active before.
 */
internal object ConfigurationRestore {
    /**
     * The sets a restore writes: hidden ones (`__constraints__`, which rtcryo saves too) describe the parameters and
     * are not written.
     */
    fun restorable(wanted: ProfileComponent): List<ConfigurationSet> =
        wanted.configurationSets.filter { !SystemCapture.isHidden(it.id) }

    /**
     * Why [wanted] cannot be written to the component with [live] configuration, or null if it can; with [strict], a
     * value outside its constraint is a reason too (see [constraintWarnings]).
     */
    fun problem(wanted: ProfileComponent, live: ConfigurationSnapshot, strict: Boolean): String? {
        for (set in restorable(wanted)) {
            val current = live.sets[set.id] ?: continue
            set.data.keys
                .firstOrNull { it !in current }
                ?.let {
                    return "no parameter '$it' in configuration set '${set.id}'"
                }
        }
        if (strict)
            constraintWarnings(wanted, live).firstOrNull()?.let {
                return it
            }
        val active = wanted.activeConfigurationSet
        if (active.isNotEmpty() && active !in live.sets && wanted.configurationSet(active) == null) {
            return "no configuration set '$active' to activate"
        }
        return null
    }

    /**
     * The values the restore would write outside the constraint their component declares, one line each (`configuration
     * set 'mode0': int_param0: '12345' is outside 0<=x<=150`). OpenRTM-aist writes them (it never checks
     * `__constraints__`); a value the component holds already is not written, so never named.
     */
    fun constraintWarnings(wanted: ProfileComponent, live: ConfigurationSnapshot): List<String> {
        val constraints = live.sets[ParameterConstraint.SET].orEmpty()
        return restorable(wanted).flatMap { set ->
            ParameterConstraint.violations(set.data, live.sets[set.id].orEmpty(), constraints).map { (name, why) ->
                "configuration set '${set.id}': $name: $why"
            }
        }
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
                    // Checked, and warned about, before the restore began.
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
