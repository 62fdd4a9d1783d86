package org.rtcoord.cli

import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.path
import java.time.LocalTime
import java.time.format.DateTimeFormatter
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.cancelChildren
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import org.rtcoord.EventOptions
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerReturned
import org.rtcoord.RtcException
import org.rtcoord.WatchMode
import org.rtcoord.cli.serve.LiveService
import org.rtcoord.cli.serve.ServeOptions
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.LiveCheck
import org.rtcoord.dsl.script.CompiledCoordinator
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost

/**
 * Runs a coordinator script against the live system until SIGINT/SIGTERM or `--for` elapses, logging how each component
 * is watched, managers that die, each rule firing, action and mode transition. On the way out the coordinator's
 * observers are detached and a summary lists each handler that failed, with the line of the script it failed at, and
 * each action that failed, and whether it stopped its handler or was only attempted; a stop by signal is a clean exit
 * (status 0). A rule that can never fire (what it names lacks its port, parameter or configuration set) is a warning at
 * start, an error with `--strict`. With `--fail-on-handler-error` the first handler that fails stops the run with
 * status 1, so that a service manager restarts it.
 */
class RunCommand : TreeCommand("run") {
    override fun help(context: Context): String =
        "Run a coordinator (SCRIPT.coord.kts, or NAME.jar compiled by rtcoord compile, which starts without compiling) until interrupted."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord -n localhost run examples/localisation.coord.kts" to "the paper's coordinator, until Ctrl-C",
            "rtcoord run --for 5m --poll 100ms restart.coord.kts 3" to "for five minutes, polling, with argument 3",
            "rtcoord -n localhost run localisation.jar" to "a coordinator compiled ahead of time (rtcoord compile)",
        )

    private val script by
        argument("SCRIPT", help = "The coordinator script, or a jar of one compiled by rtcoord compile.").path()
    private val arguments by argument("ARGS", help = "Arguments the script reads as args.").multiple()
    private val duration by
        option("--for", metavar = "DURATION", help = "Stop after this long, e.g. 30s or 5m.").duration()
    private val poll by
        option("--poll", metavar = "PERIOD", help = "Poll components at this period instead of observing them.")
            .duration()
    private val failOnHandlerError by
        option(
                "--fail-on-handler-error",
                help =
                    "Stop at the first handler that fails, with status 1 (for a service manager to restart the coordinator); " +
                        "without it a failed handler is logged and counted, and the coordinator keeps running.",
            )
            .flag()
    private val requireNameServers by
        option(
                "--require-name-servers",
                help =
                    "Exit 1 when a name server does not answer at start, instead of saying so and trying again until it does.",
            )
            .flag()
    private val strict by
        option(
                "--strict",
                help =
                    "Exit 1 at start when a rule or mode can never fire: what it names lacks the parameter or configuration set it is about " +
                        "(without it, a warning says so and the coordinator runs).",
            )
            .flag()
    private val serve by
        option("--serve", help = "Serve a live view of the system and the coordinator (see rtcoord serve).").flag()
    private val serving by ServeOptions(prefix = "serve-")
    private val logInput by LogInputOptions()

    override suspend fun execute() {
        val scripts = ScriptHost()
        val coordination =
            try {
                val apart = CompilerProcess.wanted || !CompilerJars.present
                if (apart && !CompiledCoordinator.isCompiled(script) && !scripts.isCached(script))
                    CompilerProcess.compile(script)?.let { throw ScriptFailure(it) }
                scripts.load(script, arguments, session.treeConfig())
            } catch (e: ScriptFailure) {
                // Each problem (file:line:col: message) is an error line of its own.
                e.problems.dropLast(1).forEach { echo("rtcoord: $it", err = true) }
                fail(e.problems.last(), e)
            }
        val options = poll?.let { EventOptions(WatchMode.POLL, pollPeriod = it) }
        StopSignals().use { signals ->
            var service: LiveService? = null
            val coordinator =
                Coordinator(tree, coordination, options) { line ->
                    echo("${now()} $line")
                    service?.log("coordinator", line)
                }
            // One line per component saying how it is watched (again when that changes), and one per name server
            // that stops or starts answering; the coordinator says which managers die.
            tree.onWatching { event ->
                if (event !is ManagerDied && event !is ManagerReturned) echo("${now()} ${event.path} ${event.what()}")
            }
            if (!awaitNameServers(signals, duration)) return
            val check = if (tree.nameServers.isEmpty()) null else LiveCheck(tree).check(coordination, script)
            val cannotFire = check?.cannotFire.orEmpty()
            cannotFire.forEach { echo("rtcoord: warning: $it; what names it can never fire", err = true) }
            if (strict && cannotFire.isNotEmpty())
                fail("$script: ${count(cannotFire.size, "rule or mode")} can never fire (--strict)")
            try {
                coordinator.start()
            } catch (e: RtcException) {
                // A rule's target that does not exist, is ambiguous or is of the wrong kind: nothing was started. Said
                // where, as check says it.
                val lines = check?.let { missingLines(it.missing - cannotFire.toSet(), tree) }.orEmpty()
                lines.dropLast(1).forEach { echo("rtcoord: $it", err = true) }
                fail(lines.lastOrNull() ?: "$script: ${explain(e)}", e)
            }
            logInput.start(tree)?.let { confirm("${now()} receiving log records on ${it.address}") }
            // One write: a component's watched line, printed from the tree's threads, never splits the list.
            confirm((listOf("${now()} coordinating:") + coordination.description.map { "  $it" }).joinToString("\n"))
            if (serve) {
                serving.settings().exposure()?.let { echo("rtcoord: warning: $it", err = true) }
                val top = tree.nameServers.singleOrNull() ?: tree.root
                service =
                    LiveService.start(tree, top, coordinator, options ?: coordination.watching, serving.settings()) {
                            echo("${now()} serve: $it")
                        }
                        .also { confirm("${now()} serving ${top.path} on ${it.url}") }
            }

            val signal = coroutineScope {
                if (session.verbose) launch { coordinator.failureCounts.collect { printFramesFrom(coordinator, it) } }
                if (failOnHandlerError) {
                    launch {
                        coordinator.failureCounts.first { it > 0 }
                        signals.stop(HANDLER_FAILED)
                    }
                }
                signals.await(duration).also { coroutineContext.cancelChildren() }
            }
            service?.close()
            // Detached while the ORB still works; after a signal, a second one ends the process at once.
            coordinator.stop()
            // Events the machine watched for that no transition took in the mode it was in (RunningMachine.unconsumed).
            val machines =
                coordinator.machines.joinToString("") {
                    "; ${it.name} in ${it.mode.value}, ${it.unconsumed} events no transition took"
                }
            val handlers = coordinator.handlerFailures
            val failed = coordinator.failedActions.groupingBy { it }.eachCount()
            val attempted = coordinator.failedActions.count { it.bestEffort }
            confirm(
                "${now()} stopped${signal?.let { " by $it" }.orEmpty()}; ${count(handlers.size, "handler failure")}; " +
                    "${count(failed.values.sum(), "failed action")}${if (attempted > 0) " ($attempted attempted, went on)" else ""}$machines"
            )
            handlers.forEach { confirm("  $it") }
            for ((action, times) in failed) {
                val effect = if (action.bestEffort) "attempted, went on" else "stopped its handler"
                confirm(
                    "  failed action: ${action.action}: ${action.reason} ($effect${if (times > 1) ", $times times" else ""})"
                )
            }
            if (signal == HANDLER_FAILED) throw ProgramResult(1)
        }
    }

    private var framesShown = 0

    /**
     * With -v: the script's frames of each of the first [logged] handler failures not shown yet, under its log line.
     * The count goes up once a failure's line is logged; the list has the failure a moment before.
     */
    private fun printFramesFrom(coordinator: Coordinator, logged: Int) {
        val failures = coordinator.handlerFailures.take(logged)
        failures.drop(framesShown).forEach { failure -> failure.scriptFrames.forEach { echo("    at $it") } }
        framesShown = maxOf(framesShown, failures.size)
    }

    private fun count(n: Int, what: String): String =
        "$n ${if (n == 1) what else what.split(" or ").joinToString(" or ") { "${it}s" }}"

    /**
     * Waits until every name server answers, saying which do not and when each is reached; false when stopped, or when
     * [limit] (--for) passed, meanwhile. With --require-name-servers, one that does not answer ends the run instead.
     */
    private suspend fun awaitNameServers(signals: StopSignals, limit: Duration?): Boolean {
        val waiting = TimeSource.Monotonic.markNow()
        for (server in tree.nameServers) {
            val failure = unreachable(server) ?: continue
            if (requireNameServers) fail("name server ${server.address}: ${failure.reason}", failure)
            val lost = TimeSource.Monotonic.markNow()
            echo("${now()} name server ${server.address} unreachable (${failure.reason}); trying again every $RETRY")
            while (unreachable(server) != null) {
                val left = limit?.minus(waiting.elapsedNow())
                if (left != null && !left.isPositive()) return false
                if (signals.await(left?.coerceAtMost(RETRY) ?: RETRY) != null) return false
            }
            echo(
                "${now()} name server ${server.address} reached after ${lost.elapsedNow().inWholeMilliseconds / 1000.0} s"
            )
        }
        return true
    }

    private fun now(): String = LocalTime.now().format(TIME)

    private companion object {
        const val HANDLER_FAILED = "a handler that failed (--fail-on-handler-error)"
        val TIME: DateTimeFormatter = DateTimeFormatter.ofPattern("HH:mm:ss.SSS")
        val RETRY = 1.seconds
    }
}
