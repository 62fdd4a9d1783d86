package org.rtcoord.java

import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.withContext
import org.rtcoord.EventListener
import org.rtcoord.RtcEvent
import org.rtcoord.internal.events.StandIn

/**
 * The handler that calls a Java [listener] on its executor's [dispatcher], and waits until it has returned.
 * What the listener throws comes back here and goes to the tree's failure handler, naming the listener.
 */
internal class JavaListenerCall<E : RtcEvent>(override val listener: EventListener<E>, private val dispatcher: CoroutineDispatcher) :
    suspend (E) -> Unit, StandIn {
    override suspend fun invoke(event: E) {
        withContext(dispatcher) { listener.onEvent(event) }
    }
}
