package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.default
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.option
import org.rtcoord.EventOptions
import org.rtcoord.WatchMode
import org.rtcoord.cli.serve.LiveService
import org.rtcoord.cli.serve.ServeOptions

/** `rtcoord serve`: the system as a live page in a browser. */
class ServeCommand : TreeCommand("serve") {
    override fun help(context: Context): String =
        "Serve a live view of the system below PATH to a browser: the component network laid out as a graph and " +
            "coloured by state, a filterable timeline of events, a component's details on click. Read-only unless " +
            "--operate. Runs until Ctrl-C or --for has passed."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord -n localhost serve" to "the page on http://127.0.0.1:8088/ for the name server on localhost",
        "rtcoord serve /localhost --port 9000 --operate" to "on port 9000, with buttons to activate, deactivate and reset",
        "rtcoord serve /localhost --listen 0.0.0.0 --token s3cret" to "for other hosts, at http://HOST:8088/?token=s3cret",
        "rtcoord run coordinator.coord.kts --serve" to "the coordinator's rules, modes and supervisors too",
    )

    private val path by argument("PATH", help = "A name server, context or manager; default: every name server given.").default("/")

    private val serving by ServeOptions()

    private val poll by option("--poll", metavar = "PERIOD", help = "Poll every PERIOD instead of taking pushed events.").duration()

    private val duration by option("--for", metavar = "DURATION", help = "Stop after DURATION.").duration()

    override suspend fun execute() {
        val everything = pathOf(path).isRoot
        if (everything && session.nameServers.isEmpty()) usage("no name server: give PATH (/HOST:PORT) or -n HOST")
        val top = if (everything) tree.nameServers.singleOrNull() ?: tree.root else node(path)
        serving.settings().exposure()?.let { echo("rtcoord: warning: $it", err = true) }
        val events = poll?.let { EventOptions(mode = WatchMode.POLL, pollPeriod = it) } ?: EventOptions()
        StopSignals().use { signals ->
            LiveService.start(tree, top, null, events, serving.settings()) { echo("serve: $it") }.use { service ->
                confirm("serving ${top.path} on ${service.url}")
                signals.await(duration)
            }
            // Detaches the observers while the ORB still works, as watch does.
            tree.close()
        }
    }
}
