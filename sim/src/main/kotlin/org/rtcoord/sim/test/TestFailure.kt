package org.rtcoord.sim.test

/**
 * Why a scenario failed: [at] where (`file:line:col` of the test or its coordinator), [message] what was expected and
 * what happened, in one line, and [details] what explains it (each read of a failing condition with its value, the
 * handler failure's cause, ...).
 */
public class TestFailure
internal constructor(
    /** Where: `file:line:col` (or `file:line`) of the test file or of its coordinator. */
    public val at: String,
    /** What was expected and what happened, in one line. */
    public val message: String,
    /** What explains it, a line each. */
    public val details: List<String> = emptyList(),
    /**
     * Not a failure of the coordinator: a fault of an explored schedule that could not be applied, which skips the run.
     */
    internal val skipped: Boolean = false,
) {
    /** `FILE:LINE:COL: MESSAGE`. */
    override fun toString(): String = "$at: $message"

    internal companion object {
        private val LOCATED = Regex("""^(.+?:\d+(?::\d+)?): (.*)$""")

        /** A `file:line:col: message` line (a compiler's, a script host's) as a failure. */
        fun of(problem: String): TestFailure =
            LOCATED.find(problem)?.let { TestFailure(it.groupValues[1], it.groupValues[2]) }
                ?: TestFailure("?", problem)
    }
}
