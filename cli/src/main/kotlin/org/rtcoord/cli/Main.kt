package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.CliktError
import com.github.ajalt.clikt.core.CoreCliktCommand
import com.github.ajalt.clikt.core.PrintHelpMessage
import com.github.ajalt.clikt.core.PrintMessage
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.core.subcommands
import com.github.ajalt.clikt.parsers.CommandLineParseResult
import com.github.ajalt.clikt.parsers.CommandLineParser
import kotlin.system.exitProcess

/**
 * Runs one rtcoord command and exits with its status. The explicit exit matters: JacORB leaves non-daemon threads
 * behind that would keep the JVM alive after the tree is closed.
 */
fun main(args: Array<String>) {
    useCommandLogging()
    val argv = args.asList()
    val (command, parsed) = parsedRtcoord(argv)
    val status =
        try {
            command.execute(parsed)
            0
        } catch (e: CliktError) {
            command.echoFormattedHelp(e)
            e.statusCode
        }
    exitProcess(status)
}

/**
 * Makes this JVM log as the command does; called before anything logs or makes a reference. SLF4J takes [CliLogging] as
 * it is named (instead of searching every jar for a provider) and says nothing about it, and neither JacORB nor
 * RMI-IIOP start logging of their own (see [CliLogging.JacorbSetup] and [PlainStubs]).
 */
fun useCommandLogging() {
    System.setProperty("slf4j.provider", CliLogging::class.java.name)
    System.setProperty("slf4j.internal.verbosity", "WARN")
    System.setProperty("jacorb.log.initializer", CliLogging.JacorbSetup::class.java.name)
    System.setProperty("javax.rmi.CORBA.StubClass", PlainStubs::class.java.name)
}

/** The `rtcoord` command with every subcommand. */
fun rtcoord(): Rtcoord = Rtcoord().subcommands(SUBCOMMANDS.values.map { it() })

/**
 * The `rtcoord` command to run [argv] with: only the subcommand [argv] names, when that alone parses it, since making
 * every subcommand costs a command more start-up than listing a small system; every subcommand otherwise, so that help
 * and usage errors read as they always do.
 */
fun rtcoord(argv: List<String>): Rtcoord = parsedRtcoord(argv).first

/** [rtcoord] for [argv] with [argv] parsed by it: the lone subcommand's parse is not done twice. */
internal fun parsedRtcoord(argv: List<String>): Pair<Rtcoord, CommandLineParseResult<CoreCliktCommand>> {
    fun all() = rtcoord().let { it to CommandLineParser.parse(it, argv) }
    val named = argv.firstNotNullOfOrNull { SUBCOMMANDS[it] } ?: return all()
    val alone = Rtcoord().subcommands(named())
    val parsed = CommandLineParser.parse(alone, argv)
    val subcommand = parsed.invocation.subcommandInvocations.singleOrNull()
    return if (parsed.invocation.errors.isEmpty() && subcommand != null && subcommand.errors.isEmpty()) alone to parsed
    else all()
}

/** Every subcommand, in the order help lists them, by name. */
internal val SUBCOMMANDS: Map<String, () -> CliktCommand> =
    linkedMapOf(
        "demo" to { DemoCommand() },
        "run" to { RunCommand() },
        "check" to { CheckCommand() },
        "compile" to { CompileCommand() },
        "profile" to { ProfileCommand() },
        "sim" to { SimCommand() },
        "test" to { TestCommand() },
        "ls" to { LsCommand() },
        "cat" to { CatCommand() },
        "find" to { FindCommand() },
        "act" to { ActCommand() },
        "deact" to { DeactCommand() },
        "reset" to { ResetCommand() },
        "exit" to { ExitCommand() },
        "con" to { ConCommand() },
        "dis" to { DisCommand() },
        "conf" to { ConfCommand() },
        "mgr" to { MgrCommand() },
        "del" to { DelCommand() },
        "watch" to { WatchCommand() },
        "logs" to { LogsCommand() },
        "print" to { PrintCommand() },
        "graph" to { GraphCommand() },
        "serve" to { ServeCommand() },
        "record" to { RecordCommand() },
        "help" to { HelpCommand() },
        "completion" to { CompletionCommand() },
    )

/** Parses [argv] and runs the command it names, as the overload for a parsed command line does. */
fun Rtcoord.execute(argv: List<String>): Unit = execute(CommandLineParser.parse(this, argv))

/**
 * Runs the command line this command [parsed]. Usage errors exit with status 2, as rtshell's do (Clikt's own is 1), so
 * scripts can tell a mistyped command from a failed operation.
 */
fun Rtcoord.execute(parsed: CommandLineParseResult<CoreCliktCommand>) {
    try {
        CommandLineParser.run(parsed.invocation) { it.run() }
    } catch (e: UsageError) {
        throw PrintMessage(getFormattedHelp(e).orEmpty(), statusCode = USAGE_STATUS, printError = true)
    } catch (e: PrintHelpMessage) {
        // A missing subcommand shows the help as an error.
        if (!e.error) throw e
        throw PrintMessage(getFormattedHelp(e).orEmpty(), statusCode = USAGE_STATUS, printError = true)
    }
}

private const val USAGE_STATUS = 2
