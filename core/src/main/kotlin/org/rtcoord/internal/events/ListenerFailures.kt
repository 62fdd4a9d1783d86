package org.rtcoord.internal.events

import kotlin.coroutines.AbstractCoroutineContextElement
import kotlin.coroutines.CoroutineContext
import org.rtcoord.ListenerFailure
import org.rtcoord.ListenerFailureHandler
import org.slf4j.LoggerFactory

/**
 * The tree's [ListenerFailureHandler], in the context of the tree's scope: every [EventSink] delivers in that scope and
 * finds it there, whoever created the sink.
 */
internal class ListenerFailures(private val handler: ListenerFailureHandler) : AbstractCoroutineContextElement(Key) {
    /** Tells the handler that [listener] threw [error] on [event]; if the handler throws too, both are logged. */
    fun report(listener: Any, event: Any, error: Throwable) {
        val failure = ListenerFailure(listener, event, error)
        try {
            handler.onFailure(failure)
        } catch (e: Exception) {
            ListenerFailureHandler.Log.onFailure(failure)
            log.warn("the listener failure handler {} failed on it: {}", handler, e.toString(), e)
        }
    }

    companion object Key : CoroutineContext.Key<ListenerFailures> {
        private val log = LoggerFactory.getLogger(ListenerFailures::class.java)
    }
}

/**
 * A handler that calls a listener registered in another form (a Java [org.rtcoord.EventListener] on its executor):
 * failures name [listener], not the handler.
 */
internal interface StandIn {
    /** The listener as it was registered. */
    val listener: Any
}
