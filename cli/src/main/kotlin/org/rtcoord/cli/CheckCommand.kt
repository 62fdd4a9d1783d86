package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.types.path
import java.nio.file.Path
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.LiveCheck
import org.rtcoord.dsl.ScriptCheck
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost

/**
 * Compiles coordinator scripts and evaluates them, which only declares (rules, timers, mode machines, the last checked
 * as a whole), without touching the system; lists what each declares. With a name server (`-n`), also looks up every
 * component, port, manager, naming context, profile, parameter and configuration set a script names in the live system,
 * changing nothing (see [LiveCheck]), and says what it could not check. Errors come as `file:line:col: message`; a name
 * server that does not answer is one.
 */
class CheckCommand : TreeCommand("check") {
    override fun help(context: Context): String =
        "Compile and check coordinator scripts, list what they declare, and report their errors. With -n, also report each " +
            "component, port, manager, naming context, profile, parameter and configuration set a script names (in its handlers too) " +
            "that the live system lacks, as file:line:col; names the script creates itself are said so; an unreachable name server is an error."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord check examples/*.coord.kts" to "every example's rules and modes, or its errors",
            "rtcoord -n localhost check examples/localisation.coord.kts" to
                "and whether the live system has what it names",
        )

    private val scripts by
        argument("SCRIPT", help = "Coordinator scripts (*.coord.kts).").path().multiple(required = true)

    override suspend fun execute() {
        CompilerJars.require("rtcoord check")
        val host = ScriptHost()
        // Names looked up on a name server that does not answer would all be "missing": say why once, and check none.
        val live = session.nameServers.isNotEmpty()
        val unreachable =
            if (live)
                tree.nameServers.firstNotNullOfOrNull { server ->
                    unreachable(server)?.let { "name server ${server.address}: ${it.reason}" }
                }
            else null
        var failed = false
        for (script in scripts) {
            try {
                val coordination = host.load(script, host = TreeConfig(session.nameServers, session.timeout))
                confirm("$script: compiles")
                coordination.description.forEach { confirm("  $it") }
                if (unreachable != null) {
                    echo("$script: its names cannot be checked: $unreachable", err = true)
                    failed = true
                } else if (live) {
                    failed = !report(script, LiveCheck(tree).check(coordination, script)) || failed
                }
            } catch (e: ScriptFailure) {
                e.problems.forEach { echo(it, err = true) }
                failed = true
            }
        }
        if (failed) throw ProgramResult(1)
    }

    /** Prints what [check] found of [script]; whether the live system has everything the script names. */
    private suspend fun report(script: Path, check: ScriptCheck): Boolean {
        missingLines(check.missing, tree).forEach { echo(it, err = true) }
        check.created.forEach { confirm(it.toString()) }
        if (check.unchecked.isNotEmpty()) {
            val where = check.unchecked.joinToString { "${it.at.removePrefix("$script:")} (${it.name})" }
            val names = if (check.unchecked.size == 1) "1 name" else "${check.unchecked.size} names"
            confirm("$script: not checked: $names computed as the script runs, at $where")
        }
        if (check.missing.isEmpty()) confirm("$script: everything it names is there")
        return check.missing.isEmpty()
    }
}
