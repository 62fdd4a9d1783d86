package org.rtcoord.dsl

import org.rtcoord.dsl.internal.scriptFrames

/**
 * A handler run that failed (a rule's, a timer's, a mode's action or guard, an escalation handler): [subject] says
 * which, [at] the line of the script it failed at, [type] and [message] what was thrown.
 */
public class HandlerFailure
internal constructor(
    /** Which handler: `rule 'laser0.rtc enters ERROR'`, `timer every 5s`, `entry of mode m/a`. */
    public val subject: String,
    /**
     * The script's innermost frame, as `file:line`; null when no script's code was on the way (a coordinator built in
     * code).
     */
    public val at: String?,
    /** The simple name of the exception's class. */
    public val type: String,
    /** What the exception says. */
    public val message: String,
    /** Every frame of the script on the way to the failure, innermost first, as `file:line (method)`. */
    public val scriptFrames: List<String>,
) {
    /** One line: `SUBJECT failed at FILE:LINE: TYPE: MESSAGE`. */
    override fun toString(): String = "$subject failed${at?.let { " at $it" }.orEmpty()}: $type: $message"

    internal companion object {
        fun of(subject: String, error: Throwable): HandlerFailure {
            val frames = scriptFrames(error)
            val message = error.message ?: "(no message)"
            return HandlerFailure(
                subject,
                frames.firstOrNull()?.let { "${it.fileName}:${it.lineNumber}" },
                error.javaClass.simpleName,
                message,
                frames.map { "${it.fileName}:${it.lineNumber} (${it.className}.${it.methodName})" },
            )
        }
    }
}
