package org.rtcoord.cli

import com.github.ajalt.clikt.core.BaseCliktCommand
import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.PrintHelpMessage
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple

/** `rtcoord help [COMMAND]...`: the same help as `rtcoord COMMAND... --help`, as git users expect. */
class HelpCommand : CliktCommand("help") {
    override fun help(context: Context): String = "Show the help of COMMAND (and its subcommand), or of rtcoord itself."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord help conf" to "what conf does, its options and examples",
            "rtcoord help mgr create" to "the same for a subcommand",
        )

    private val command by argument("COMMAND", help = "A command, as `rtcoord --help` lists them.").multiple()

    override fun run() {
        throw helpOf(command)
    }
}

/**
 * What `rtcoord COMMAND... --help` shows, as the message Clikt prints it from. A word that names no command is a usage
 * error (Clikt would show the help of the last command it knew instead).
 */
internal fun helpOf(command: List<String>): PrintHelpMessage {
    command.fold<String, BaseCliktCommand<*>>(rtcoord()) { parent, word ->
        parent.registeredSubcommands().firstOrNull { it.commandName == word }
            ?: throw UsageError(
                "no such command: $word (${parent.commandName} has ${parent.registeredSubcommandNames().joinToString(", ")})"
            )
    }
    try {
        rtcoord().execute(command + "--help")
    } catch (e: PrintHelpMessage) {
        return e
    }
    error("--help did not ask for help")
}
