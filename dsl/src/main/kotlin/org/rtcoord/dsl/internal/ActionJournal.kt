package org.rtcoord.dsl.internal

import kotlin.coroutines.AbstractCoroutineContextElement
import kotlin.coroutines.CoroutineContext

/** How to take back one completed action, when it can be taken back. */
internal typealias Undo = suspend () -> Unit

/**
 * The actions a handler completed so far, in order, each with its [Undo] where it has one: what a [ReactionFailure]
 * reports and undoes. Carried in the handler's coroutine context, so that the actions of references (which know nothing
 * of the handler) record themselves.
 */
internal class ActionJournal : AbstractCoroutineContextElement(ActionJournal) {
    /** One completed action: its log line, and how to undo it (null: it cannot be undone). */
    class Entry(val what: String, val undo: Undo?)

    private val entries = java.util.concurrent.CopyOnWriteArrayList<Entry>()

    val done: List<Entry>
        get() = entries.toList()

    fun record(what: String, undo: Undo?) {
        entries += Entry(what, undo)
    }

    companion object Key : CoroutineContext.Key<ActionJournal>
}

/** Marks the actions of an [Reaction.attempt] block: their failures are warnings, not the handler's end. */
internal class BestEffort private constructor() : AbstractCoroutineContextElement(BestEffort) {
    companion object Key : CoroutineContext.Key<BestEffort> {
        val element = BestEffort()
    }
}
