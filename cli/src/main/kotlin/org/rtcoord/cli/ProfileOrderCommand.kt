package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import kotlin.time.Duration.Companion.seconds
import org.rtcoord.cli.json.PlannedStepJson
import org.rtcoord.cli.json.StepOutcomeJson
import org.rtcoord.profile.OrderedAction

/** `rtcoord profile start|stop`: rtstart and rtstop, in the profile's Activation or Deactivation order. */
class ProfileOrderCommand(name: String, private val action: OrderedAction) : ProfileFileCommand(name) {
    override fun help(context: Context): String =
        "${if (action == OrderedAction.START) "Activate" else "Deactivate"} the profile's components in the order of its " +
            "${if (action == OrderedAction.START) "Activation" else "Deactivation"} section: sequence numbers, WaitTime and " +
            "Preceding (SYNC or ASYNC, with timeout). Each step has a deadline; the report says what was and was not done."

    private val dryRun by option("--dry-run", help = "Print the plan, one step a line, and change nothing.").flag()

    private val deadline by
        option("--step-deadline", metavar = "DURATION", help = "How long one step may take beyond its condition.")
            .duration()
            .default(10.seconds)

    override suspend fun execute() {
        val profile = profile()
        if (dryRun) {
            val plan = refusing { profiles.plan(profile, action) }
            if (session.json) {
                echoJson(plan.map { PlannedStepJson(it.sequence, it.component, it.contextId, it.condition.toString()) })
            } else {
                plan.forEach { echo(it.toString()) }
            }
            return
        }
        val outcomes = refusing { profiles.run(profile, action, deadline) }
        if (session.json) {
            echoJson(outcomes.map { StepOutcomeJson(it.step.toString(), it.done, it.atMillis, it.detail) })
        } else {
            outcomes.forEach { if (it.done) confirm(it.toString()) else echo(it.toString()) }
        }
        val failed = outcomes.count { !it.done }
        if (failed > 0) throw CommandFailed("$failed of ${outcomes.size} steps not done")
    }
}
