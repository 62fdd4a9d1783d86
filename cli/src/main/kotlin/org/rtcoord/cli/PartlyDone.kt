package org.rtcoord.cli

import org.rtcoord.RtcException

/**
 * A command of several steps that failed at one of them: [failure] says why, [progress] which steps were done before it
 * and which were not attempted, so the user knows exactly what changed.
 */
class PartlyDone(val failure: RtcException, val progress: String) : Exception("${failure.message}; $progress", failure)

/**
 * Runs [step] on each of [targets] in order, stopping at the first failure. When there are other targets, the failure
 * says what became of them: `DONE: A, B; not attempted: C` ([done] is the past participle of the step, `activated`,
 * `disconnected`); [name] names a target.
 */
internal suspend fun <T> eachInTurn(targets: List<T>, done: String, name: (T) -> String, step: suspend (T) -> Unit) {
    targets.forEachIndexed { index, target ->
        try {
            step(target)
        } catch (e: RtcException) {
            val before = targets.take(index).map(name)
            val after = targets.drop(index + 1).map(name)
            if (before.isEmpty() && after.isEmpty()) throw e
            val notAttempted = after.takeIf { it.isNotEmpty() }?.let { "not attempted: ${it.joinToString()}" }
            throw PartlyDone(
                e,
                listOfNotNull("$done: ${before.joinToString().ifEmpty { "none" }}", notAttempted).joinToString("; "),
            )
        }
    }
}
