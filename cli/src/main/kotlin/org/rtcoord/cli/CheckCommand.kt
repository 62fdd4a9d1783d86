package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.types.path
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost

/**
 * Compiles coordinator scripts and evaluates them, which only declares (rules, timers, mode machines,
 * the last checked as a whole), without touching the system; lists what each declares. Errors come as
 * `file:line:col: message`.
 */
class CheckCommand : TreeCommand("check") {
    override fun help(context: Context): String = "Compile and check coordinator scripts, list what they declare, and report their errors."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord check examples/*.coord.kts" to "every example's rules and modes, or its errors",
    )

    private val scripts by argument("SCRIPT", help = "Coordinator scripts (*.coord.kts).").path().multiple(required = true)

    override suspend fun execute() {
        val host = ScriptHost()
        var failed = false
        for (script in scripts) {
            try {
                val coordination = host.load(script, host = TreeConfig(session.nameServers, session.timeout))
                confirm("$script: compiles")
                coordination.description.forEach { confirm("  $it") }
            } catch (e: ScriptFailure) {
                e.problems.forEach { echo(it, err = true) }
                failed = true
            }
        }
        if (failed) throw ProgramResult(1)
    }
}
