package org.rtcoord.cli.serve

import com.github.ajalt.clikt.parameters.groups.OptionGroup
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.path
import com.github.ajalt.clikt.parameters.types.restrictTo
import java.nio.file.Path
import org.rtcoord.listenAddressProblem

/**
 * How the live view is served: where it listens, the token its requests must carry and whether the page may operate
 * components. [prefix] is put before each option's name (`--serve-port` for `run`).
 */
class ServeOptions(prefix: String = "") : OptionGroup("Live view") {
    /** The port to listen on; 0 lets the system choose. */
    val port: Int by
        option("--${prefix}port", metavar = "N", help = "The port the page is served on; 0 picks a free one.")
            .int()
            .restrictTo(0..65535)
            .default(DEFAULT_PORT)

    /** The one address to listen on. */
    val address: String by
        option(
                "--${prefix}listen",
                metavar = "ADDRESS",
                help =
                    "The address the page is served on (default 127.0.0.1). Any other lets other hosts see the system: " +
                        "add --${prefix}token.",
            )
            .convert { address -> listenAddressProblem(address)?.let { fail(it) } ?: address }
            .default(LOOPBACK)

    /** The token every API request must carry, or null when none is required. */
    val token: String? by
        option(
                "--${prefix}token",
                metavar = "TOKEN",
                help = "Require TOKEN in the page's requests: open http://HOST:PORT/?token=TOKEN.",
            )
            .convert { token ->
                token.takeIf { it.isNotBlank() && it.none(Char::isWhitespace) } ?: fail("a token is one word")
            }

    /** Whether the page may operate components: lifecycle, connections, configuration. */
    val operate: Boolean by
        option(
                "--${prefix}operate",
                help =
                    "Let the page activate, deactivate, reset and exit components, connect and disconnect ports, set configuration " +
                        "values and switch sets; every action is logged.",
            )
            .flag()

    /** Where to record what the page shows, or null. */
    val record: Path? by
        option(
                "--${prefix}record",
                metavar = "FILE",
                help =
                    "Write what the page shows to FILE as JSON lines, the snapshot first, then every event: replay it with serve --replay FILE.",
            )
            .path(canBeDir = false)

    /** The settings chosen. */
    internal fun settings(): ServeSettings = ServeSettings(address, port, token, operate, record)

    private companion object {
        const val DEFAULT_PORT = 8088
        const val LOOPBACK = "127.0.0.1"
    }
}
