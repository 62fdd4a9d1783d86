package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.cli.json.CreatedJson

/** `rtcoord mgr PATH create TYPE`: a new component through the manager. */
class MgrCreateCommand(private val mgr: MgrCommand) : TreeCommand("create") {
    override fun help(context: Context): String =
        "Create a component of TYPE (a factory's implementation id) and print its path. The manager loads a module " +
            "for TYPE if it needs one; a master manager has a slave create it. A refusal names the manager, its factories and loadable modules."

    private val type by argument("TYPE", help = "The component type.")

    private val name by
        option("--name", metavar = "N", help = "The instance name (default: the manager's, TYPE plus a number).")

    override suspend fun execute() {
        val created = manager(mgr.path).create(type, name)
        if (session.json) echoJson(CreatedJson(created.path.toString())) else confirm(created.path.toString())
    }
}
