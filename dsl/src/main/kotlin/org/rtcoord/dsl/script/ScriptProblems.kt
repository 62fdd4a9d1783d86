package org.rtcoord.dsl.script

import java.nio.file.Files
import java.nio.file.Path
import kotlin.script.experimental.api.ScriptDiagnostic
import kotlin.script.experimental.api.SourceCode
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcException
import org.rtcoord.dsl.InvalidMachineException

/**
 * What a script's compiler and evaluation report, as the `file:line:col: message` lines rtcoord prints: errors only,
 * each with a hint where one fits ([CompileHints]); for coordinators (compiled now or ahead of time) and for the
 * `*.test.kts` tests of `rtcoord test` alike.
 */
@InternalRtcoordApi
public object ScriptProblems {
    /** The errors of [reports] on [script], a line each; one line saying it failed when none says more. */
    public fun of(script: Path, reports: List<ScriptDiagnostic>): List<String> {
        val text by lazy { runCatching { Files.readString(script) }.getOrNull() }
        return reports
            .filter { it.severity >= ScriptDiagnostic.Severity.ERROR }
            .map { report ->
                val location = report.location
                val written = location?.let { at -> text?.let { excerpt(it, at) } }
                val message = report.exception?.let(::thrownMessage) ?: CompileHints.withHint(report.message, written)
                "${report.sourcePath ?: script}:${location?.start?.line ?: 1}:${location?.start?.col ?: 1}: $message"
            }
            .ifEmpty { listOf("$script:1:1: compilation failed") }
    }

    /**
     * Where a script's body threw [error], as `location:line:1: message`: [location] is a path or file name ending in
     * the script's name, the line the deepest frame in that file.
     */
    public fun thrown(location: String, error: Throwable): String {
        val fileName = location.substringAfterLast('/').substringAfterLast('\\')
        val frame =
            generateSequence(error) { it.cause }
                .flatMap { it.stackTrace.asSequence() }
                .firstOrNull { it.fileName == fileName }
        return "$location:${frame?.lineNumber ?: 1}:1: ${thrownMessage(error)}"
    }

    /**
     * What [error] says to a script's author: the message alone when the DSL or core threw it on purpose (a bad name,
     * an invalid machine: `require` and `check` included); a programming error's class too.
     */
    public fun thrownMessage(error: Throwable): String {
        val message = error.message
        val meant =
            error is IllegalArgumentException ||
                error is IllegalStateException ||
                error is RtcException ||
                error is InvalidMachineException
        return if (meant && message != null) message else "${error.javaClass.simpleName}: ${message ?: "(no message)"}"
    }

    /** The code [location] spans on one line of [text]; null when it spans several or is not known. */
    private fun excerpt(text: String, location: SourceCode.Location): String? {
        val end = location.end ?: return null
        if (end.line != location.start.line) return null
        val line = text.lineSequence().drop(location.start.line - 1).firstOrNull() ?: return null
        // Columns count from 1; the end is the column just after the code.
        val from = (location.start.col - 1).coerceIn(0, line.length)
        return line.substring(from, (end.col - 1).coerceIn(from, line.length)).ifEmpty { null }
    }
}
