package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.PrintMessage
import com.github.ajalt.clikt.core.UsageError
import com.github.ajalt.clikt.core.context
import com.github.ajalt.clikt.core.registerCloseable
import com.github.ajalt.clikt.core.terminal
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.eagerOption
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.multiple
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.mordant.terminal.Terminal
import java.util.Properties
import kotlin.time.Duration.Companion.seconds
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.listenAddressProblem
import org.rtcoord.nameServerPath

/**
 * The root command: global options that say where the system is and how to talk about it. Its [run] turns them into the
 * [Session] every subcommand uses, and registers the session with the context so the tree is closed when the command
 * ends, however it ends.
 */
class Rtcoord : CliktCommand(name = "rtcoord") {
    init {
        // Read only when asked for: finding the resource costs every command a few milliseconds.
        eagerOption("--version", help = "Show the version and exit") { throw PrintMessage("rtcoord ${version()}") }
        context {
            helpFormatter = ::HelpFormatter
            terminal = Terminal(terminalInterface = PlainTerminal)
            // Listings print thousands of plain lines: those skip Mordant's rendering, which would change
            // nothing in them and costs more than printing them.
            val rendered = echoMessage
            echoMessage = { context, message, trailingLinebreak, stderr ->
                if (message is String && printsAsIs(message)) {
                    context.terminal.rawPrint(if (trailingLinebreak) "$message\n" else message, stderr)
                } else {
                    rendered(context, message, trailingLinebreak, stderr)
                }
            }
        }
    }

    override fun help(context: Context): String =
        "Browse and operate an OpenRTM-aist RT system: name servers, naming contexts, managers and components, " +
            "addressed by rtshell's paths (/host:port/context/name.rtc:port)."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord -n localhost ls -l" to
                "the root context of the name server on localhost:2809, as rtls -l /localhost/ lists it",
            "rtcoord -n localhost ls -l -R" to "state and ports of everything that name server knows",
            "rtcoord -n localhost act host.host_cxt/laser0.rtc" to
                "a relative path starts at the first name server given",
            "rtcoord act /localhost/host.host_cxt/laser0.rtc" to "activate a component and wait until it is Active",
            "RTCOORD_NAMESERVERS='a;b:2810' rtcoord find / --state error" to "components in ERROR on two name servers",
        ) +
            "\n\nRelative paths start from RTCOORD_CWD (or rtshell's RTCSH_CWD) when it is set, else at the first name server " +
            "given (-n or RTCOORD_NAMESERVERS). A name that is not found is answered with the close ones that exist (did you mean)."

    private val nameServers by
        option(
                "-n",
                "--nameserver",
                metavar = "ADDRESS",
                help =
                    "A name server to use, HOST or HOST:PORT (repeatable). Without it: RTCOORD_NAMESERVERS, else rtshell's " +
                        "RTCTREE_NAMESERVERS, both separated by ';'. Name servers named in a path are always used. Relative paths " +
                        "start at the first one, unless RTCOORD_CWD says otherwise.",
            )
            .convert { address -> nameServer(address) { fail(it) } }
            .multiple()

    private val timeout by
        option(
                "--timeout",
                metavar = "DURATION",
                help = "How long any one call to the system may take, e.g. 3s or 500ms.",
            )
            .duration()
            .default(3.seconds)

    private val listen by
        option(
                "--listen",
                metavar = "ADDRESS",
                help =
                    "The one address to listen on for components calling back (watch, run, demo). Default: the address this " +
                        "host uses to reach the first name server, loopback for a local one. 0.0.0.0 listens on every interface.",
            )
            .convert { address -> listenAddressProblem(address)?.let { fail(it) } ?: address }

    private val json by option("--json", help = "Machine-readable output (JSON) from every listing command.").flag()

    private val verbose by
        option("-v", "--verbose", help = "Turn JacORB's logging on and show the stack trace of an error.").flag()

    private val quiet by
        option("-q", "--quiet", help = "Print no confirmations or progress; listings and errors still print.").flag()

    override fun run() {
        if (verbose) CliLogging.verbose()
        val session =
            Session(
                nameServers = nameServers.ifEmpty { nameServersFromEnvironment() },
                timeout = timeout,
                json = json,
                verbose = verbose,
                quiet = quiet,
                workingDirectory = workingDirectoryFromEnvironment(),
                listenAddress = listen,
            )
        currentContext.findOrSetObject { currentContext.registerCloseable(session) }
    }

    private fun nameServersFromEnvironment(): List<String> {
        val variable =
            NAME_SERVER_VARIABLES.firstOrNull { !currentContext.readEnvvar(it).isNullOrBlank() } ?: return emptyList()
        return currentContext
            .readEnvvar(variable)!!
            .split(';')
            .map { it.trim() }
            .filter { it.isNotEmpty() }
            .map { address -> nameServer(address) { throw UsageError("$variable: $it") } }
    }

    private fun workingDirectoryFromEnvironment(): RtcPath? {
        val variable = CWD_VARIABLES.firstOrNull { !currentContext.readEnvvar(it).isNullOrBlank() } ?: return null
        val text = currentContext.readEnvvar(variable)!!
        return try {
            RtcPath(text)
        } catch (e: RtcException) {
            throw UsageError("$variable: ${e.message}")
        }
    }

    internal companion object {
        /**
         * Whether Mordant prints [text] as it is: it expands tabs and interprets escape sequences, and leaves text
         * without control characters (newlines apart) unchanged.
         */
        private fun printsAsIs(text: String): Boolean = text.none { it.isISOControl() && it != '\n' }

        private val NAME_SERVER_VARIABLES = listOf("RTCOORD_NAMESERVERS", "RTCTREE_NAMESERVERS")
        private val CWD_VARIABLES = listOf("RTCOORD_CWD", "RTCSH_CWD")

        /** [address] if it is `host`, `host:port` or a name server's `corbaloc:`; else [invalid] with why. */
        private inline fun nameServer(address: String, invalid: (String) -> Nothing): String =
            try {
                nameServerPath(address)
                address
            } catch (e: RtcException) {
                invalid(e.message ?: "'$address' is not HOST[:PORT]")
            }

        /** The project version the jar was built as. */
        fun version(): String =
            Rtcoord::class.java.getResourceAsStream("version.properties")?.use {
                Properties().apply { load(it) }.getProperty("version")
            } ?: "unknown"
    }
}
