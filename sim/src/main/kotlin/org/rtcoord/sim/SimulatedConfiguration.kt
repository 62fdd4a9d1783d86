package org.rtcoord.sim

import org.rtcoord.profile.ProfileComponent
import org.rtcoord.runtime.ParameterSpec

/**
 * A saved component's configuration as the simulated component holds it: every set the profile saved, hidden ones
 * (`__constraints__`, `__widget__`) included, each with exactly its values; parameters are those the visible sets name,
 * each defaulting to its value in `default` (else the first set naming it).
 *
 * A parameter whose `__constraints__` entry is a numeric range (`0<=x<=150`, `x<10`) is taken to be a number: a value
 * that is not one gives the variable its default, as OpenRTM-aist's transform of a numeric variable does
 * (`Config.update`). A value outside the range is stored and used, as it is on the real component, which never reads
 * its constraints; rtcoord's `conf set` and `profile restore` warn about it there and here alike (and refuse it with
 * `--strict`).
 */
internal class SimulatedConfiguration(component: ProfileComponent) {
    private val all: Map<String, Map<String, String>> = component.configurationSets.associate { it.id to it.data }
    private val visible = all.filterKeys { !isHidden(it) }
    private val constraints = all[CONSTRAINTS].orEmpty()

    /** The parameters, in the order `default` (then each other set) names them. */
    val parameters: List<ParameterSpec> = run {
        val defaults = visible["default"] ?: visible.values.firstOrNull().orEmpty()
        (defaults.keys + visible.values.flatMap { it.keys }).distinct().map { name ->
            val default = defaults[name] ?: visible.values.firstNotNullOf { it[name] }
            val numeric = constraints[name]?.let(::isNumericRange) == true && default.trim().toDoubleOrNull() != null
            if (numeric) ParameterSpec(name, default) { it.trim().toDoubleOrNull() != null }
            else ParameterSpec(name, default)
        }
    }

    /** The sets besides `default`, hidden ones too, each with exactly the values saved. */
    val sets: Map<String, Map<String, String>> = all.filterKeys { it != "default" }

    private companion object {
        const val CONSTRAINTS = "__constraints__"

        fun isHidden(set: String) = set.startsWith("__") && set.endsWith("__")

        /** `0<=x<=150`, `x<10`, `-1.5<x`: a bound on `x`, which only a number can meet. */
        fun isNumericRange(constraint: String) =
            'x' in constraint && constraint.any { it == '<' || it == '>' } && '(' !in constraint
    }
}
