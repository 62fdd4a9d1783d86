package org.rtcoord.cli.serve

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.conflate
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.merge
import org.rtcoord.dsl.Coordinator

/**
 * What the page shows of a running [Coordinator]: each rule with its last firing and failures, each
 * mode machine's active mode path and recent history, each supervisor's children, restarts and
 * back-off. Read from the coordinator's observable state, never from its log.
 */
internal class CoordinatorView(private val coordinator: Coordinator) {
    /** The view, and again each time anything it shows changes: the coordinator's own flows, merged. */
    fun updates(): Flow<Map<String, Any?>> {
        val sources: List<Flow<Any?>> = listOf(coordinator.failureCounts) +
            coordinator.rules.map { it.status } +
            coordinator.machines.flatMap { listOf(it.mode, it.history, it.unconsumedCounts) } +
            coordinator.supervision.map { it.status }
        return sources.merge().conflate().map { toJson() }.distinctUntilChanged()
    }

    /** The view as JSON-ready maps. */
    fun toJson(): Map<String, Any?> = mapOf(
        "failures" to coordinator.failures,
        "rules" to coordinator.rules.map { rule ->
            val status = rule.status.value
            mapOf(
                "description" to rule.description,
                "firings" to status.firings,
                "lastFired" to status.lastFired?.toString(),
                "lastEvent" to status.lastEvent,
                "failures" to status.failures,
                "lastFailure" to status.lastFailure,
            )
        },
        "machines" to coordinator.machines.map { machine ->
            mapOf(
                "name" to machine.name,
                "mode" to machine.mode.value,
                // Every mode, nested by path, so that the page draws the machine and marks the active path in it.
                "modes" to machine.model.modes.map { mode -> mapOf("path" to mode.path, "name" to mode.name, "parent" to mode.parent?.path) },
                "unconsumed" to machine.unconsumed,
                "history" to machine.history.value.takeLast(HISTORY_SHOWN).map { move ->
                    mapOf("from" to move.from, "to" to move.to, "trigger" to move.trigger, "at" to move.at.toString())
                },
            )
        },
        "supervisors" to coordinator.supervision.map { supervisor ->
            val status = supervisor.status.value
            mapOf(
                "name" to supervisor.name,
                "strategy" to supervisor.strategy,
                "children" to status.children,
                "restarts" to status.restarts,
                "lastRestart" to status.lastRestart?.toString(),
                "lastRestarted" to status.lastRestarted,
                "backoffMillis" to status.backoff?.inWholeMilliseconds,
                "waitingUntil" to status.waitingUntil?.toString(),
                "escalation" to status.escalation,
            )
        },
    )

    private companion object {
        /** Transitions the page lists per machine: the latest ones. */
        const val HISTORY_SHOWN = 50
    }
}
