package org.rtcoord

import org.slf4j.LoggerFactory

/**
 * An event listener or handler that threw, or whose executor refused its task: [listener] as it was registered (a
 * Kotlin handler passed to [RtcTree.on] or [RtcTree.onWatching], a Java [EventListener], a listener of a coordinator's
 * `subscribe...`), the [event] it was given and the [error] it threw. The listener keeps receiving the events that
 * follow.
 */
public class ListenerFailure(
    /** The handler or listener that threw, as it was registered. */
    public val listener: Any,
    /**
     * What it was given: the [RtcEvent] for an event listener or handler; for a listener of a coordinator's
     * `subscribe...`, the change as a `Map.Entry` (the rule, machine or supervisor, and its status).
     */
    public val event: Any,
    /** What it threw. */
    public val error: Throwable,
) {
    override fun toString(): String = "listener $listener failed on $event: $error"
}

/**
 * Receives every [ListenerFailure] of a tree ([TreeConfig.listenerFailures]), on the thread of the delivery that
 * failed. It should return quickly; a failure of its own is logged with the one it was given.
 */
public fun interface ListenerFailureHandler {
    /** Called once for each time a listener or handler threw. */
    public fun onFailure(failure: ListenerFailure)

    /**
     * The handler trees have by default: logs each failure as a warning, with the listener, the event and the stack
     * trace of what it threw. Java: `ListenerFailureHandler.Log.INSTANCE`.
     */
    public object Log : ListenerFailureHandler {
        override fun onFailure(failure: ListenerFailure) {
            LoggerFactory.getLogger(ListenerFailure::class.java)
                .warn(
                    "listener {} failed on {}: {}",
                    failure.listener,
                    failure.event,
                    failure.error.toString(),
                    failure.error,
                )
        }

        override fun toString(): String = "ListenerFailureHandler.Log"
    }
}
