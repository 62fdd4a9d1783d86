package org.rtcoord

/** Receives events, for Java callers of [org.rtcoord.java.JavaTree.subscribe]. */
public fun interface EventListener<E : RtcEvent> {
    /** Called with each event, one at a time, in the order of the source's events. */
    public fun onEvent(event: E)
}
