package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.default
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.convert
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.path
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.DurationUnit
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import org.rtcoord.EventOptions
import org.rtcoord.WatchMode
import org.rtcoord.cli.serve.Chromium
import org.rtcoord.cli.serve.LiveService
import org.rtcoord.cli.serve.Recording
import org.rtcoord.cli.serve.ServeOptions

/** `rtcoord serve`: the system as a live page in a browser. */
class ServeCommand : TreeCommand("serve") {
    override fun help(context: Context): String =
        "Serve a live view of the system below PATH to a browser: components coloured by state with their ports, " +
            "connectors between ports, naming contexts as boxes, a filterable timeline of events, a component's details " +
            "on click. Read-only unless --operate. --record writes what the page shows to a file; --replay plays such a " +
            "file back. Runs until Ctrl-C or --for has passed."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord -n localhost serve" to "the page on http://127.0.0.1:8088/ for the name server on localhost",
            "rtcoord serve /localhost --port 9000 --operate" to "on port 9000, where the page may operate components",
            "rtcoord serve /localhost --listen 0.0.0.0 --token s3cret" to
                "for other hosts, at http://HOST:8088/?token=s3cret",
            "rtcoord run coordinator.coord.kts --serve" to "the coordinator's rules, modes and supervisors too",
            "rtcoord serve /localhost --record run.jsonl" to "the page, and what it shows written to run.jsonl",
            "rtcoord serve --replay run.jsonl" to "the recorded run played back, with a time slider",
            "rtcoord serve --replay run.jsonl --screenshot moment.png --at 12.5s" to
                "a picture of the run 12.5 s after its start",
            "rtcoord serve /localhost --screenshot system.png" to
                "a picture of the page, taken by headless Chromium; then exit",
        )

    private val path by
        argument("PATH", help = "A name server, context or manager; default: every name server given.").default("/")

    private val serving by ServeOptions()
    private val logInput by LogInputOptions()

    private val poll by
        option("--poll", metavar = "PERIOD", help = "Poll every PERIOD instead of taking pushed events.").duration()

    private val duration by option("--for", metavar = "DURATION", help = "Stop after DURATION.").duration()

    private val replay by
        option(
                "--replay",
                metavar = "FILE",
                help = "Play back a run recorded with --record (or rtcoord record) instead of following a system.",
            )
            .path(mustExist = true, canBeDir = false, mustBeReadable = true)

    private val screenshot by
        option(
                "--screenshot",
                metavar = "FILE.png",
                help =
                    "Take a picture of the page with headless Chromium (on the PATH, or RTCOORD_CHROMIUM), save it to FILE.png and exit; " +
                        "with --replay, of the recording at --at.",
            )
            .path(canBeDir = false)

    private val at by
        option(
                "--at",
                metavar = "TIME",
                help =
                    "With --replay: the moment of the recording the page opens at (and --screenshot pictures), from its start, e.g. 12.5s; default: its start.",
            )
            .convert("TIME") { text ->
                Duration.parseOrNull(text)?.takeUnless { it.isNegative() }
                    ?: fail("'$text' is not a time such as 12.5s")
            }

    override suspend fun execute() {
        replay?.let { file ->
            if (pathOf(path).isRoot.not()) usage("--replay plays a recording: give no PATH")
            return replaying(file)
        }
        if (at != null) usage("--at is a moment of a recording: give --replay FILE")
        val top = systemTop(path)
        serving.settings().exposure()?.let { echo("rtcoord: warning: $it", err = true) }
        val events = poll?.let { EventOptions(mode = WatchMode.POLL, pollPeriod = it) } ?: EventOptions()
        StopSignals().use { signals ->
            logInput.start(tree)?.let { echo("serve: receiving log records on ${it.address}") }
            LiveService.start(tree, top, null, events, serving.settings()) { echo("serve: $it") }
                .use { service ->
                    val picture = screenshot
                    if (picture != null) {
                        // Without the event stream (?once), which would keep the picture's virtual time from passing.
                        withContext(Dispatchers.IO) {
                            Chromium.screenshot(service.url + (if ('?' in service.url) "&" else "?") + "once", picture)
                        }
                        confirm("saved a picture of ${top.path} to $picture")
                    } else {
                        confirm("serving ${top.path} on ${service.url}")
                        signals.await(duration)
                    }
                }
            // Detaches the observers while the ORB still works, as watch does.
            tree.close()
        }
    }

    private suspend fun replaying(file: Path) {
        val recording = Recording.read(file)
        val moment = at ?: Duration.ZERO
        if (moment > recording.length)
            throw CommandFailed("$file lasts ${recording.length}: it has no moment $moment after its start")
        StopSignals().use { signals ->
            LiveService.replay(recording, serving.settings()).use { service ->
                val url =
                    service.url + (if ('?' in service.url) "&" else "?") + "at=${moment.toDouble(DurationUnit.SECONDS)}"
                val picture = screenshot
                if (picture != null) {
                    withContext(Dispatchers.IO) { Chromium.screenshot(url, picture) }
                    confirm("saved a picture of $file at $moment to $picture")
                } else {
                    confirm("replaying $file on $url")
                    signals.await(duration)
                }
            }
        }
    }
}
