package org.rtcoord.cli

import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.NotFoundException
import org.rtcoord.PreconditionNotMetException
import org.rtcoord.cli.json.ConfigurationJson

/** Whether [id] names one of OpenRTM's hidden configuration sets (`__constraints__`, `__widget__`, ...). */
internal fun isHiddenSet(id: String): Boolean = id.startsWith("__") && id.endsWith("__")

/** The sets to show, by id: only set [only] when given, else all but the hidden ones unless [showHidden]. */
internal fun ConfigurationSnapshot.shownSets(
    showHidden: Boolean,
    only: String? = null,
): Map<String, Map<String, String>> =
    sets.toSortedMap().filterKeys { id -> if (only != null) id == only else showHidden || !isHiddenSet(id) }

/** [sets] as text: each set's id (the active one marked `*`), its parameters below it. */
internal fun ConfigurationSnapshot.lines(sets: Map<String, Map<String, String>>, indent: String): List<String> =
    sets.flatMap { (id, parameters) ->
        listOf("$indent${if (id == activeSet) "* " else "  "}$id") + aligned(sorted(parameters), "$indent    ")
    }

/** [sets] for `--json`, with the active set's id (null when none is active). */
internal fun ConfigurationSnapshot.toJson(sets: Map<String, Map<String, String>>): ConfigurationJson =
    ConfigurationJson(activeSet, sets.mapValues { (_, parameters) -> parameters.toSortedMap() })

/** The error for a configuration set [id] that [component] does not have among [sets]. */
internal fun noSuchSet(component: ComponentNode, id: String, sets: Set<String>): NotFoundException =
    NotFoundException(component.path.toString(), "no configuration set '$id' (sets: ${sets.sorted().joinToString()})")

/** The error for [operation] on the active set of [component], which has none. */
internal fun noActiveSet(
    component: ComponentNode,
    operation: String,
    configuration: ConfigurationSnapshot,
): PreconditionNotMetException =
    PreconditionNotMetException(
        component.path.toString(),
        operation,
        "no configuration set is active: name one with --set, or activate one (sets: ${configuration.sets.keys.sorted().joinToString()})",
    )
