package org.rtcoord.dsl.script

import org.rtcoord.RtcException
import org.rtcoord.dsl.InvalidMachineException

/** How a script's failure reads to its author: `file:line:col: message`, from a script compiled now or ahead of time. */
internal object ScriptErrors {
    /** The line of [location] (a path or file name ending in the script's name) at which [error] was thrown by the script's body. */
    fun thrown(location: String, error: Throwable): String {
        val fileName = location.substringAfterLast('/').substringAfterLast('\\')
        val frame = generateSequence(error) { it.cause }.flatMap { it.stackTrace.asSequence() }.firstOrNull { it.fileName == fileName }
        return "$location:${frame?.lineNumber ?: 1}:1: ${message(error)}"
    }

    /**
     * What [error] says to a script's author: the message alone when the DSL or core threw it on purpose
     * (a bad name, an invalid machine: `require` and `check` included); a programming error's class too.
     */
    fun message(error: Throwable): String {
        val message = error.message
        val meant = error is IllegalArgumentException || error is IllegalStateException || error is RtcException || error is InvalidMachineException
        return if (meant && message != null) message else "${error.javaClass.simpleName}: ${message ?: "(no message)"}"
    }
}
