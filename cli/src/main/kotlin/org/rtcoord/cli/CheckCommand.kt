package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.types.path
import org.rtcoord.dsl.script.ScriptHost

/** Compiles coordinator scripts without running them; errors come as `file:line:col: message`. */
class CheckCommand : TreeCommand("check") {
    override fun help(context: Context): String = "Compile coordinator scripts and report their errors."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord check examples/*.coord.kts" to "every example compiles, or its errors are listed",
    )

    private val scripts by argument("SCRIPT", help = "Coordinator scripts (*.coord.kts).").path().multiple(required = true)

    override suspend fun execute() {
        val host = ScriptHost()
        var failed = false
        for (script in scripts) {
            val errors = host.check(script)
            errors.forEach { echo(it, err = true) }
            if (errors.isEmpty()) confirm("$script: compiles") else failed = true
        }
        if (failed) throw ProgramResult(1)
    }
}
