package org.rtcoord.dsl.internal

/**
 * A supervisor's log: each line starts with the supervisor's [name]; a recovery step is logged before it runs, and
 * again if it fails.
 */
internal class RecoveryLog(private val name: String, private val log: (String) -> Unit) {
    /** Logs [text] as the supervisor's. */
    fun line(text: String) = log("$name: $text")

    /** Runs one recovery step, logged as [what]; a failure is logged with the step and gives null. */
    suspend fun <T> attempt(what: String, action: suspend () -> T): T? {
        line(what)
        return catchFailure({ action() }) { e ->
            line("$what failed: ${e.message ?: e}")
            null
        }
    }
}
