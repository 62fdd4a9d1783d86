package org.rtcoord.cli

import kotlinx.coroutines.flow.toList
import org.rtcoord.NodeFilters
import org.rtcoord.NodeKind
import org.rtcoord.RtcTree
import org.rtcoord.dsl.NameFinding

/**
 * [missing] as `check` and `run` print them, `file:line:col: name: reason`, a component not found with the components
 * of [tree] whose names are close to it ("did you mean").
 */
internal suspend fun missingLines(missing: List<NameFinding>, tree: RtcTree): List<String> {
    if (missing.isEmpty()) return emptyList()
    val components = tree.find(predicate = NodeFilters.kind(NodeKind.COMPONENT)).toList().map { it.name }
    return missing.map {
        if ("no such component" in it.says) "$it${didYouMean(it.name, components)}" else it.toString()
    }
}
