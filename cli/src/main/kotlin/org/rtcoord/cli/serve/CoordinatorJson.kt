package org.rtcoord.cli.serve

import kotlinx.serialization.Serializable

/**
 * A running coordinator as the page shows it ([CoordinatorView] makes it): its handler [failures], its rules, mode
 * machines and supervisors. Times are ISO-8601 in UTC.
 */
@Serializable
internal data class CoordinatorJson(
    val failures: Int,
    val rules: List<RuleJson>,
    val machines: List<MachineJson>,
    val supervisors: List<SupervisorJson>,
)

/** A rule: how often it fired, when last and on what, and its handler's failures. */
@Serializable
internal data class RuleJson(
    val description: String,
    val firings: Int,
    val lastFired: String?,
    val lastEvent: String?,
    val failures: Int,
    val lastFailure: String?,
)

/** A mode machine: its active [mode]'s path, every mode, the events it left unconsumed and its latest transitions. */
@Serializable
internal data class MachineJson(
    val name: String,
    val mode: String?,
    val modes: List<ModeJson>,
    val unconsumed: Int,
    val history: List<ModeMoveJson>,
)

/** A mode by its [path] (names joined by `/`), with its [parent]'s path. */
@Serializable internal data class ModeJson(val path: String, val name: String, val parent: String?)

/** A transition from [from] (null at the start) to [to], on [trigger], [at] a time. */
@Serializable internal data class ModeMoveJson(val from: String?, val to: String, val trigger: String, val at: String)

/**
 * A supervisor: its children's paths, its restarts, the back-off it waits out, and why it gave up once it escalated.
 */
@Serializable
internal data class SupervisorJson(
    val name: String,
    val strategy: String,
    val children: List<String>,
    val restarts: Int,
    val lastRestart: String?,
    val lastRestarted: String?,
    val backoffMillis: Long?,
    val waitingUntil: String?,
    val escalation: String?,
)
