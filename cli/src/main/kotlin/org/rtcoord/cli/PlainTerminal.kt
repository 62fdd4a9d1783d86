package org.rtcoord.cli

import com.github.ajalt.mordant.rendering.AnsiLevel
import com.github.ajalt.mordant.rendering.Size
import com.github.ajalt.mordant.terminal.PrintRequest
import com.github.ajalt.mordant.terminal.TerminalInfo
import com.github.ajalt.mordant.terminal.TerminalInterface

/**
 * The terminal Clikt prints through, without Mordant's detection, which costs about 70 ms on every start (native calls
 * through JNA, a child process, JMX): plain text, interactive when the JVM has a console, as wide as COLUMNS says.
 * Every print is flushed, so `watch` reaches a pipe line by line. A standard output with no reader any more (`rtcoord
 * print PORT | head`) stops the command that runs until stopped ([StopSignals.outputClosed]): the JVM ignores SIGPIPE
 * and [java.io.PrintStream] keeps the broken pipe to itself, so the command went on printing to nobody for good.
 */
internal object PlainTerminal : TerminalInterface {
    private val console = System.console() != null

    override fun info(
        ansiLevel: AnsiLevel?,
        hyperlinks: Boolean?,
        outputInteractive: Boolean?,
        inputInteractive: Boolean?,
    ): TerminalInfo =
        TerminalInfo(
            ansiLevel = ansiLevel ?: AnsiLevel.NONE,
            ansiHyperLinks = hyperlinks ?: false,
            outputInteractive = outputInteractive ?: console,
            inputInteractive = inputInteractive ?: console,
            supportsAnsiCursor = false,
        )

    override fun completePrintRequest(request: PrintRequest) {
        val stream = if (request.stderr) System.err else System.out
        if (request.trailingLinebreak) stream.println(request.text) else stream.print(request.text)
        // checkError flushes standard output before it answers: one flush a line, as for standard error.
        if (request.stderr) stream.flush() else if (stream.checkError()) StopSignals.outputClosed()
    }

    override fun readLineOrNull(hideInput: Boolean): String? = readlnOrNull()

    override fun getTerminalSize(): Size? = null
}
