package org.rtcoord.dsl

import org.rtcoord.dsl.internal.ActionJournal
import org.rtcoord.dsl.internal.catchFailure

/**
 * Why a handler stopped, as its [Reaction.onFailure] blocks see it: the failure and the actions the handler completed
 * before it, which [undo] takes back.
 */
public class ReactionFailure
internal constructor(
    /** The failure that stopped the handler. */
    public val cause: Exception,
    private val journal: List<ActionJournal.Entry>,
    private val log: (String) -> Unit,
) {
    /** The actions the handler completed before it failed, oldest first, as the log wrote them. */
    public val done: List<String>
        get() = journal.map { it.what }

    private var undone = false

    /**
     * Takes back the completed actions, newest first: an activation by a deactivation, a connection by a disconnection,
     * a disconnection by the same connection made again, a creation by the created component's exit. A reset, an exit,
     * a deletion or a configuration change cannot be taken back: each is logged as not undone. Each undo is a best
     * effort: one that fails is logged as a warning and the others still run. Runs once; later calls do nothing.
     * Returns whether every action was taken back.
     */
    public suspend fun undo(): Boolean {
        if (undone) return true
        undone = true
        var complete = true
        for (entry in journal.asReversed()) {
            val undo = entry.undo
            if (undo == null) {
                log("not undone: ${entry.what}")
                complete = false
                continue
            }
            catchFailure({ undo() }) { e ->
                log("warning: undoing '${entry.what}' failed: ${e.message ?: e}")
                complete = false
            }
        }
        return complete
    }

    override fun toString(): String = cause.message ?: cause.toString()
}
