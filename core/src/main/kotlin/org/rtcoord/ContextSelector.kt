package org.rtcoord

/** Picks one of a component's execution contexts. */
public sealed class ContextSelector {
    /** The context the component knows by [handle] (owned: 0.., participating: 1000..). */
    public data class Handle(val handle: Int) : ContextSelector()

    /** The [index]th context counting owned ones first, then participating ones: rtshell's `-e`. */
    public data class Index(val index: Int) : ContextSelector()

    public companion object {
        /** The component's first owned context, handle 0. */
        @JvmField
        public val DEFAULT: ContextSelector = Handle(0)
    }
}
