package org.rtcoord.cli.json

import kotlinx.serialization.Serializable

/** A difference `profile check --json` found between the profile and the running system. */
@Serializable internal class DifferenceJson(val subject: String, val expected: String, val actual: String)

/**
 * A step of `profile start|stop --dry-run --json`: its [sequence], the [component], its [context]'s id and when it may
 * run.
 */
@Serializable
internal class PlannedStepJson(val sequence: Int, val component: String, val context: Int, val condition: String)

/** What became of one step of `profile start|stop --json`, [atMillis] from the start of the run. */
@Serializable
internal class StepOutcomeJson(val step: String, val done: Boolean, val atMillis: Long, val detail: String)

/** What `profile restore --json` did, kept as it was, could not find, created, and warned of; one line per item. */
@Serializable
internal class RestoreJson(
    val done: List<String>,
    val kept: List<String>,
    val missingOptional: List<String>,
    val created: List<String>,
    val warnings: List<String>,
)
