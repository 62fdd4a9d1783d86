package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import org.rtcoord.DEFAULT_LOG_ADDRESS
import org.rtcoord.EventOptions
import org.rtcoord.Node
import org.rtcoord.PortTraffic
import org.rtcoord.RtcEvent
import org.rtcoord.SystemSnapshot
import org.rtcoord.WatchMode
import org.rtcoord.cli.json.EventDetail
import org.rtcoord.cli.json.EventJson
import org.rtcoord.cli.json.FsmJson
import org.rtcoord.cli.json.OneLineJson
import org.rtcoord.cli.json.WatchMethodJson

/** `rtcoord watch`: rtwatch that starts, for every kind of event, pushed where components allow it. */
class WatchCommand : TreeCommand("watch") {
    override fun help(context: Context): String =
        "Print events as they happen, one line each: when the tree noticed it, the path, what happened. Components push " +
            "them through their ComponentObserver when they accept one, else they are polled: a line per component says " +
            "which (and why), and again when that changes. A manager that stops answering is one line naming the " +
            "components that went with it. A context or manager watches everything below it, including components that " +
            "appear later. Runs until Ctrl-C, SIGTERM or --for has passed, then exits 0."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord watch /localhost/host.host_cxt/laser0.rtc" to
                "the laser's state, ports, configuration and contexts",
            "rtcoord watch /localhost/host.host_cxt --poll 200ms --for 1m" to
                "a whole context, polled five times a second, for a minute",
            "rtcoord --json watch /localhost/host.host_cxt | jq .event" to "one JSON object per line",
            "rtcoord watch --data /localhost/host.host_cxt/laser0.rtc" to
                "the laser's events and the rate of its scans, every second",
            "rtcoord watch --logs /localhost/host.host_cxt" to
                "the context's events, and the log records its components send to 127.0.0.1:24224",
        )

    private val paths by argument("PATH", help = "Components, naming contexts or managers.").multiple(required = true)

    private val poll by
        option("--poll", metavar = "PERIOD", help = "Poll every PERIOD instead of taking pushed events.").duration()

    private val duration by option("--for", metavar = "DURATION", help = "Stop after DURATION.").duration()

    private val data by
        option(
                "--data",
                help =
                    "Also watch the data: every second a line per data out-port with the rate it sends at (the tree taps each " +
                        "one), and the ports' traffic as their components report it.",
            )
            .flag()

    private val logs by
        option(
                "--logs",
                help =
                    "Also receive the components' log records and print them among the events (on " +
                        "${DEFAULT_LOG_ADDRESS} unless --logs-listen says where).",
            )
            .flag()

    private val input by LogInputOptions()

    override suspend fun execute() {
        val options = poll?.let { EventOptions(mode = WatchMode.POLL, pollPeriod = it) } ?: EventOptions()
        StopSignals().use { signals ->
            // Subscribed one by one, each returning once its components are read and observed: a wrong
            // path fails before anything is printed, and --for counts from when every event is caught.
            val events = Channel<RtcEvent>(Channel.UNLIMITED)
            val nodes = paths.map { node(it) }
            // Traffic comes only to who names it: with --data.
            val types = if (data) setOf(RtcEvent::class.java, PortTraffic::class.java) else setOf(RtcEvent::class.java)
            // The system as it is when every event is caught, then what changes: nothing lost in between.
            tree.follow(nodes, types, options, start = { snapshot -> presentLines(snapshot, nodes).forEach(::echo) }) {
                events.send(it)
            }
            val rates = if (data) PortRates.tap(nodes) else null
            input.start(tree, DEFAULT_LOG_ADDRESS.takeIf { logs })?.let { listening ->
                echo("${timestamp(System.currentTimeMillis())} receiving log records on ${listening.address}")
            }
            coroutineScope {
                val printing = launch {
                    for (event in events) if (session.json) echo(OneLineJson.encodeToString(EventJson.of(event)))
                    else echo(event.line())
                }
                val reporting = rates?.let { launch { it.report(session.json) { line -> echo(line) } } }
                signals.await(duration)
                // Closing the tree while still subscribed detaches every observer before it returns;
                // ending the subscriptions first would leave that to background work the exit cuts short.
                tree.close()
                reporting?.cancel()
                printing.cancel()
            }
        }
    }

    /**
     * A line per component below [nodes] with its state, per name server of theirs that does not answer, and per
     * manager found dead that is, or hosted a component that is, below them, as [snapshot] has them.
     */
    private fun presentLines(snapshot: SystemSnapshot, nodes: List<Node>): List<String> {
        val now = System.currentTimeMillis()
        val servers =
            snapshot.nameServers
                .filter { entry -> !entry.reachable && nodes.any { it.path.nameServer == entry.node.address } }
                .map { entry ->
                    if (session.json) {
                        OneLineJson.encodeToString(
                            EventJson.found(now, entry.node.path, EventDetail.NameServerLost(entry.cause?.message))
                        )
                    } else {
                        "${timestamp(now)} ${entry.node.path} name server unreachable (${entry.cause?.reason})"
                    }
                }
        val components =
            snapshot.components
                .filter { entry -> nodes.any { entry.isAtOrBelow(it.path) } }
                .map { entry ->
                    val read = entry.node.snapshots.value
                    val what = if (!entry.alive) "unreachable" else read?.brief(entry.state) ?: entry.state.name
                    val method = entry.watchMethod
                    // An FSM's state entered before every event was caught is told here, or it would be told nowhere.
                    val fsm = entry.fsm
                    if (session.json) {
                        val present =
                            EventDetail.Present(
                                entry.state.name,
                                read?.let { EventDetail.connections(it) },
                                fsm?.let(FsmJson::of),
                                entry.alive,
                            )
                        OneLineJson.encodeToString(
                            EventJson.found(now, entry.path, present, method?.let(WatchMethodJson::of))
                        )
                    } else {
                        "${timestamp(now)} ${entry.path} $what" +
                            (fsm?.let { ", FSM state ${it.text()}" } ?: "") +
                            (method?.let { "; watched: ${it.text()}" } ?: "")
                    }
                }
        // A manager that died while the watch started is in the snapshot, not among the events after it.
        val managers =
            snapshot.managerOutages
                .filter { died ->
                    nodes.any { node ->
                        died.source.path.startsWith(node.path) ||
                            died.components.any { hosted -> snapshot.component(hosted)?.isAtOrBelow(node.path) == true }
                    }
                }
                .map { died -> if (session.json) OneLineJson.encodeToString(EventJson.of(died)) else died.line() }
        return servers + components + managers
    }
}
