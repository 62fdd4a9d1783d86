package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.option
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import org.rtcoord.DEFAULT_LOG_ADDRESS
import org.rtcoord.LogLevel
import org.rtcoord.LogRecord
import org.rtcoord.cli.json.EventJson
import org.rtcoord.cli.json.OneLineJson

/** `rtcoord logs`: the components' log records as they come, which rtshell cannot show. */
class LogsCommand : TreeCommand("logs") {
    override fun help(context: Context): String =
        "Receive the components' log records (OpenRTM-aist 2.x sends them to a Fluentd forward input) and print them " +
            "as they come, one line each: when rtcoord received it, the component, manager or (when the tree has not " +
            "listed its sender) the root that sent it, its level, logger and message. PATH narrows them to the " +
            "records of a component, or of what a context or manager holds. Runs until Ctrl-C, SIGTERM or --for has " +
            "passed, then exits 0; what the input refused is said on the way out."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord -n localhost logs" to "every record sent to 127.0.0.1:24224",
            "rtcoord -n localhost logs --level WARN --grep timeout /localhost/host.host_cxt/laser0.rtc" to
                "the laser's warnings and errors that mention a timeout",
            "rtcoord --json logs --logs-listen 0.0.0.0:24224 --logs-key secret | jq .message" to
                "records from other hosts, which must know the key, one JSON object per line",
        )

    private val paths by argument("PATH", help = "Components, naming contexts or managers (default: all).").multiple()

    private val level by
        option("--level", metavar = "LEVEL", help = "Only records at LEVEL or above (FATAL ... PARANOID; default all).")
            .convert { name ->
                LogLevel.named(name) ?: fail("'$name' is no log level (${LogLevel.entries.joinToString()})")
            }
            .default(LogLevel.PARANOID)

    private val grep by
        option("--grep", metavar = "REGEX", help = "Only records whose message REGEX finds.").convert { pattern ->
            runCatching { Regex(pattern) }.getOrElse { fail("'$pattern' is no regular expression: ${it.message}") }
        }

    private val since by
        option(
                "--since",
                metavar = "DURATION",
                help =
                    "Only records their senders stamped at most DURATION ago: leaves out what a sender kept while it could not send.",
            )
            .duration()

    private val duration by option("--for", metavar = "DURATION", help = "Stop after DURATION.").duration()

    private val input by LogInputOptions()

    override suspend fun execute() {
        StopSignals().use { signals ->
            val from = since?.let { System.currentTimeMillis() - it.inWholeMilliseconds }
            // Handed over one at a time: a terminal slower than the records holds them in the tree's bounded queue,
            // whose oldest are dropped and counted (said on the way out), not in this process's heap.
            val records = Channel<LogRecord>()
            val nodes = if (paths.isEmpty()) listOf(tree.root) else paths.map { node(it) }
            nodes.forEach { node -> tree.on(node, LogRecord::class.java) { records.send(it) } }
            val listening = checkNotNull(input.start(tree, DEFAULT_LOG_ADDRESS))
            echo("rtcoord: receiving log records on ${listening.address}", err = true)
            coroutineScope {
                val printing = launch {
                    // A record reaches each of overlapping PATHs: printed once, by its place in the tree's events.
                    val printed = LinkedHashSet<Long>()
                    for (record in records) {
                        if (!printed.add(record.sequence)) continue
                        if (printed.size > DEDUPLICATED) printed.remove(printed.first())
                        if (!record.level.atLeast(level) || (from != null && record.loggedAt < from)) continue
                        if (grep?.containsMatchIn(record.message) == false) continue
                        echo(if (session.json) OneLineJson.encodeToString(EventJson.of(record)) else record.line())
                    }
                }
                signals.await(duration)
                printing.cancel()
            }
            val refused = listening.refusals().filterValues { it > 0 }
            if (refused.isNotEmpty())
                echo("rtcoord: refused: ${refused.entries.joinToString { (why, count) -> "$count $why" }}", err = true)
        }
    }

    private companion object {
        /** Enough sequence numbers to tell a record reaching two PATHs at once. */
        const val DEDUPLICATED = 1024
    }
}
