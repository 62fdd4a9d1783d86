package org.rtcoord

import org.rtcoord.internal.ValueFields

/** Picks one of a component's execution contexts. */
public sealed class ContextSelector {
    /** The kind of selector and its number: two selectors are equal when these are. */
    internal abstract fun fields(): ValueFields

    final override fun equals(other: Any?): Boolean = other is ContextSelector && fields() == other.fields()

    final override fun hashCode(): Int = fields().hashCode()

    final override fun toString(): String = fields().toString()

    /** The context the component knows by [handle] (owned: 0.., participating: 1000..). */
    public class Handle(public val handle: Int) : ContextSelector() {
        override fun fields(): ValueFields = ValueFields("Handle", "handle" to handle)
    }

    /** The [index]th context counting owned ones first, then participating ones: rtshell's `-e`. */
    public class Index(public val index: Int) : ContextSelector() {
        override fun fields(): ValueFields = ValueFields("Index", "index" to index)
    }

    public companion object {
        /** The component's first owned context, handle 0. */
        @JvmField
        public val DEFAULT: ContextSelector = Handle(0)
    }
}
