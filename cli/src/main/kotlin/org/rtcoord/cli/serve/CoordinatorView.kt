package org.rtcoord.cli.serve

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.conflate
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.merge
import org.rtcoord.dsl.Coordinator

/**
 * What the page shows of a running [Coordinator]: each rule with its last firing and failures, each mode machine's
 * active mode path and recent history, each supervisor's children, restarts and back-off. Read from the coordinator's
 * observable state, never from its log.
 */
internal class CoordinatorView(private val coordinator: Coordinator) {
    /** The view, and again each time anything it shows changes: the coordinator's own flows, merged. */
    fun updates(): Flow<CoordinatorJson> {
        val sources: List<Flow<Any?>> =
            listOf(coordinator.failureCounts) +
                coordinator.rules.map { it.status } +
                coordinator.machines.flatMap { listOf(it.mode, it.history, it.unconsumedCounts) } +
                coordinator.supervision.map { it.status }
        return sources.merge().conflate().map { toJson() }.distinctUntilChanged()
    }

    /** The view as the page reads it. */
    fun toJson(): CoordinatorJson =
        CoordinatorJson(
            failures = coordinator.failures,
            rules =
                coordinator.rules.map { rule ->
                    val status = rule.status.value
                    RuleJson(
                        rule.description,
                        status.firings,
                        status.lastFired?.toString(),
                        status.lastEvent,
                        status.failures,
                        status.lastFailure,
                    )
                },
            machines =
                coordinator.machines.map { machine ->
                    MachineJson(
                        name = machine.name,
                        mode = machine.mode.value,
                        // Every mode, nested by path, so that the page draws the machine and marks the active path in
                        // it.
                        modes = machine.model.modes.map { mode -> ModeJson(mode.path, mode.name, mode.parent?.path) },
                        unconsumed = machine.unconsumed,
                        history =
                            machine.history.value.takeLast(HISTORY_SHOWN).map { move ->
                                ModeMoveJson(move.from, move.to, move.trigger, move.at.toString())
                            },
                    )
                },
            supervisors =
                coordinator.supervision.map { supervisor ->
                    val status = supervisor.status.value
                    SupervisorJson(
                        name = supervisor.name,
                        strategy = supervisor.strategy,
                        children = status.children,
                        restarts = status.restarts,
                        lastRestart = status.lastRestart?.toString(),
                        lastRestarted = status.lastRestarted,
                        backoffMillis = status.backoff?.inWholeMilliseconds,
                        waitingUntil = status.waitingUntil?.toString(),
                        escalation = status.escalation,
                    )
                },
        )

    private companion object {
        /** Transitions the page lists per machine: the latest ones. */
        const val HISTORY_SHOWN = 50
    }
}
