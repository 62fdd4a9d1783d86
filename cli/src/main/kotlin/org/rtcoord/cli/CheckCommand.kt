package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.types.path
import kotlinx.coroutines.flow.toList
import org.rtcoord.NodeFilters
import org.rtcoord.NodeKind
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.runtime.LiveCheck
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost

/**
 * Compiles coordinator scripts and evaluates them, which only declares (rules, timers, mode machines,
 * the last checked as a whole), without touching the system; lists what each declares. With a name
 * server (`-n`), also looks up every component, port, manager, parameter and configuration set a script
 * names in the live system, changing nothing. Errors come as `file:line:col: message`.
 */
class CheckCommand : TreeCommand("check") {
    override fun help(context: Context): String =
        "Compile and check coordinator scripts, list what they declare, and report their errors. With -n, also report each " +
            "component, port, manager, parameter and configuration set a script names that the live system lacks, as file:line:col."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord check examples/*.coord.kts" to "every example's rules and modes, or its errors",
        "rtcoord -n localhost check examples/localisation.coord.kts" to "and whether the live system has what it names",
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
                if (session.nameServers.isNotEmpty()) {
                    val text = script.toFile().readText()
                    val missing = LiveCheck(tree).missing(coordination)
                    val components = if (missing.isEmpty()) emptyList() else tree.find(predicate = NodeFilters.kind(NodeKind.COMPONENT)).toList().map { it.name }
                    missing.forEach { echo("$script:${positionOf(it.name, text)}: ${it.name}: ${it.reason}${didYouMean(it.name, components)}", err = true) }
                    if (missing.isEmpty()) confirm("$script: everything it names is there") else failed = true
                }
            } catch (e: ScriptFailure) {
                e.problems.forEach { echo(it, err = true) }
                failed = true
            }
        }
        if (failed) throw ProgramResult(1)
    }

    /** Where [name] is written in [text], as `line:col` (1-based): as a string literal, else its last `:` part (a port); else 1:1. */
    private fun positionOf(name: String, text: String): String {
        val at = listOf("\"$name\"", "\"${name.substringAfterLast(':')}\"").map { text.indexOf(it) }.firstOrNull { it >= 0 } ?: return "1:1"
        val before = text.substring(0, at + 1)
        return "${before.count { it == '\n' } + 1}:${at - before.lastIndexOf('\n')}"
    }
}
