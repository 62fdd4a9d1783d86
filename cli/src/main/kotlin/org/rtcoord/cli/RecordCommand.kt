package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.default
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.path
import org.rtcoord.EventOptions
import org.rtcoord.WatchMode
import org.rtcoord.cli.serve.LiveRecorder
import org.rtcoord.cli.serve.LiveView

/** `rtcoord record`: what the live view would show, written to a file to replay later. */
class RecordCommand : TreeCommand("record") {
    override fun help(context: Context): String =
        "Record the system below PATH to FILE as JSON lines, as the live view sees it: the snapshot first, then every " +
            "event and change of shape. Replay it with rtcoord serve --replay FILE. Runs until Ctrl-C or --for has passed."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord -n localhost record run.jsonl" to "the name server's system, until Ctrl-C",
            "rtcoord record run.jsonl /localhost/host.host_cxt --for 5m" to "one context, for five minutes",
            "rtcoord serve --replay run.jsonl" to "the recording in a browser, with a time slider",
        )

    private val file by argument("FILE", help = "The file to write (replaced).").path(canBeDir = false)

    private val path by
        argument("PATH", help = "A name server, context or manager; default: every name server given.").default("/")

    private val poll by
        option("--poll", metavar = "PERIOD", help = "Poll every PERIOD instead of taking pushed events.").duration()

    private val duration by option("--for", metavar = "DURATION", help = "Stop after DURATION.").duration()

    private val logInput by LogInputOptions()

    override suspend fun execute() {
        val top = systemTop(path)
        val events = poll?.let { EventOptions(mode = WatchMode.POLL, pollPeriod = it) } ?: EventOptions()
        StopSignals().use { signals ->
            logInput.start(tree)?.let { confirm("receiving log records on ${it.address}") }
            LiveView(tree, top, null, events, operable = false).use { view ->
                view.start()
                LiveRecorder.start(view, file).use {
                    confirm("recording ${top.path} to $file")
                    signals.await(duration)
                }
            }
            // Detaches the observers while the ORB still works, as watch does.
            tree.close()
        }
    }
}
