package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * Picks one of a component's execution contexts. Operations take the component's first owned context, `Handle(0)`,
 * unless given one.
 */
public sealed class ContextSelector : ValueObject() {
    /** The context the component knows by [handle] (owned: 0.., participating: 1000..). */
    public class Handle(public val handle: Int) : ContextSelector() {
        override fun fields(): ValueFields = ValueFields("handle" to handle)
    }

    /** The [index]th context counting owned ones first, then participating ones: rtshell's `-e`. */
    public class Index(public val index: Int) : ContextSelector() {
        override fun fields(): ValueFields = ValueFields("index" to index)
    }
}
