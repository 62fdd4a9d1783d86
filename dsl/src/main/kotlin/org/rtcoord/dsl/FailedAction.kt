package org.rtcoord.dsl

/**
 * An action of the coordinator that failed: [action] as the log wrote it, [reason] as the system
 * answered, and whether it was a best effort ([Reaction.attempt]), after which its handler went on.
 */
public data class FailedAction(val action: String, val reason: String, val bestEffort: Boolean)
