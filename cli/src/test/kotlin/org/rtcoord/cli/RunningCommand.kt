package org.rtcoord.cli

import com.github.ajalt.clikt.core.context
import com.github.ajalt.clikt.core.terminal
import com.github.ajalt.clikt.testing.CliktCommandTestResult
import com.github.ajalt.clikt.testing.test
import com.github.ajalt.mordant.terminal.PrintRequest
import com.github.ajalt.mordant.terminal.Terminal
import com.github.ajalt.mordant.terminal.TerminalInterface
import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import java.util.concurrent.TimeoutException
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * `rtcoord ARGUMENTS` running in the background of this JVM through Clikt's test harness, its stdout read line by line
 * as it is printed: a test waits for the line it expects ([awaitLine]) instead of a fixed `--for` window, then [stop]s
 * the command as Ctrl-C would and reads the whole result.
 */
class RunningCommand(vararg arguments: String) : AutoCloseable {
    private val lines = mutableListOf<String>()
    private val partial = StringBuilder()
    private val lock = Object()

    /** The run's result, once it has ended. */
    val result: CompletableFuture<CliktCommandTestResult> =
        CompletableFuture.supplyAsync {
                val command = rtcoord()
                command.test(arguments.toList()) { argv ->
                    // After the harness's own configuration: its recorder still gets every print.
                    command.context { terminal = Terminal(terminalInterface = LineTap(terminal.terminalInterface)) }
                    command.execute(argv)
                }
            }
            .whenComplete { _, _ -> synchronized(lock) { lock.notifyAll() } }

    /** The stdout lines printed so far. */
    val printed: List<String>
        get() = synchronized(lock) { lines.toList() }

    /**
     * Waits until a stdout line printed since the start satisfies [line] and returns it; fails naming [what] and
     * showing the output when none does within [timeout] or the command ends first.
     */
    fun awaitLine(what: String, timeout: Duration = 60.seconds, line: (String) -> Boolean): String =
        awaitOutput(what, timeout) { it.firstOrNull(line) }

    /** Waits until [count] stdout lines satisfy [line] and returns them all. */
    fun awaitLines(what: String, count: Int, timeout: Duration = 60.seconds, line: (String) -> Boolean): List<String> =
        awaitOutput(what, timeout) { printed -> printed.filter(line).takeIf { it.size >= count } }

    private fun <T : Any> awaitOutput(what: String, timeout: Duration, found: (List<String>) -> T?): T {
        val deadline = TimeSource.Monotonic.markNow() + timeout
        synchronized(lock) {
            while (true) {
                found(lines)?.let {
                    return it
                }
                val left = -deadline.elapsedNow()
                if (result.isDone || !left.isPositive()) break
                lock.wait(left.inWholeMilliseconds.coerceAtLeast(1))
            }
        }
        val ended = if (result.isDone) "the command ended" else "$timeout passed"
        throw AssertionError(
            "$ended before $what; stdout:\n${printed.joinToString("\n")}\nstderr:\n${runCatching { result.getNow(null)?.stderr }.getOrNull().orEmpty()}"
        )
    }

    /** Stops the command as a SIGINT would and returns its result; fails when it does not end within [timeout]. */
    fun stop(timeout: Duration = 60.seconds): CliktCommandTestResult {
        val deadline = TimeSource.Monotonic.markNow() + timeout
        // Until the command waits for a signal, a stop finds nothing to stop: asked again until it ends.
        while (!result.isDone) {
            StopSignals.interrupt()
            if (!(-deadline.elapsedNow()).isPositive())
                throw AssertionError("the command did not stop within $timeout; stdout:\n${printed.joinToString("\n")}")
            try {
                result.get(50.milliseconds.inWholeMilliseconds, TimeUnit.MILLISECONDS)
            } catch (e: TimeoutException) {
                // Not ended yet.
            }
        }
        return result.get()
    }

    override fun close() {
        if (!result.isDone) stop()
    }

    /** Passes every print on to [recorder], and stdout lines to [lines] as they are completed. */
    private inner class LineTap(private val recorder: TerminalInterface) : TerminalInterface by recorder {
        override fun completePrintRequest(request: PrintRequest) {
            recorder.completePrintRequest(request)
            if (request.stderr) return
            synchronized(lock) {
                partial.append(request.text)
                if (request.trailingLinebreak) partial.append('\n')
                while ('\n' in partial) {
                    val end = partial.indexOf("\n")
                    lines += partial.substring(0, end)
                    partial.delete(0, end + 1)
                }
                lock.notifyAll()
            }
        }
    }
}

/**
 * Runs `rtcoord ARGUMENTS` until a stdout line satisfies [until], then stops it as Ctrl-C would; returns its result.
 */
fun runRtcoordUntil(vararg arguments: String, what: String, until: (String) -> Boolean): CliktCommandTestResult =
    RunningCommand(*arguments).use { running ->
        running.awaitLine(what, line = until)
        running.stop()
    }
