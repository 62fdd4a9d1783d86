package org.rtcoord

import org.rtcoord.internal.ValueFields

/** Picks one of a component's execution contexts. */
public sealed class ContextSelector : ValueObject() {
    /** The context the component knows by [handle] (owned: 0.., participating: 1000..). */
    public class Handle(public val handle: Int) : ContextSelector() {
        override fun fields(): ValueFields = ValueFields("handle" to handle)
    }

    /** The [index]th context counting owned ones first, then participating ones: rtshell's `-e`. */
    public class Index(public val index: Int) : ContextSelector() {
        override fun fields(): ValueFields = ValueFields("index" to index)
    }

    public companion object {
        /** The component's first owned context, handle 0. */
        @JvmField
        public val DEFAULT: ContextSelector = Handle(0)
    }
}
