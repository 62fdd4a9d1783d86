package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.PrintHelpMessage
import com.github.ajalt.clikt.core.PrintMessage
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.core.parse
import com.github.ajalt.clikt.core.subcommands
import kotlin.system.exitProcess

/**
 * Runs one rtcoord command and exits with its status. The explicit exit matters: JacORB leaves
 * non-daemon threads behind that would keep the JVM alive after the tree is closed.
 */
fun main(args: Array<String>) {
    val command = rtcoord()
    val status = try {
        command.execute(args.asList())
        0
    } catch (e: CliktError) {
        command.echoFormattedHelp(e)
        e.statusCode
    }
    exitProcess(status)
}

/** The `rtcoord` command with every subcommand. */
fun rtcoord(): Rtcoord = Rtcoord().subcommands(
    DemoCommand(),
    RunCommand(),
    CheckCommand(),
    LsCommand(),
    CatCommand(),
    FindCommand(),
    ActCommand(),
    DeactCommand(),
    ResetCommand(),
    ExitCommand(),
    ConCommand(),
    DisCommand(),
    ConfCommand(),
    MgrCommand(),
    DelCommand(),
    WatchCommand(),
    GraphCommand(),
)

/**
 * Parses [argv] and runs the command it names. Usage errors exit with status 2, as rtshell's do
 * (Clikt's own is 1), so scripts can tell a mistyped command from a failed operation.
 */
fun Rtcoord.execute(argv: List<String>) {
    try {
        parse(argv)
    } catch (e: UsageError) {
        throw PrintMessage(getFormattedHelp(e).orEmpty(), statusCode = USAGE_STATUS, printError = true)
    } catch (e: PrintHelpMessage) {
        // A missing subcommand shows the help as an error.
        if (!e.error) throw e
        throw PrintMessage(getFormattedHelp(e).orEmpty(), statusCode = USAGE_STATUS, printError = true)
    }
}

private const val USAGE_STATUS = 2
