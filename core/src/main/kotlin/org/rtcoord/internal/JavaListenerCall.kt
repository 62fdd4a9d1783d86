package org.rtcoord.internal

import java.util.concurrent.Executor
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.atomic.AtomicBoolean
import org.rtcoord.EventListener
import org.rtcoord.RtcEvent
import org.rtcoord.internal.events.StandIn
import org.slf4j.LoggerFactory

/**
 * The handler that calls a Java [listener] on its [executor] and waits until it has returned. What the listener throws,
 * and the executor's refusal of the task, come back here and go to the tree's failure handler, naming the listener. A
 * refusal is logged too, once per registration: it usually means the caller's toolkit has gone (SWT's display disposed)
 * and every later event will be refused as well.
 */
internal class JavaListenerCall<E : RtcEvent>(
    override val listener: EventListener<in E>,
    private val executor: Executor,
    /** What the events are given as: the registration delivers only events of this type. */
    private val type: Class<E>,
) : suspend (RtcEvent) -> Unit, StandIn {
    private val refusalLogged = AtomicBoolean()

    override suspend fun invoke(event: RtcEvent) {
        val delivered = type.cast(event)
        try {
            executor.runTask { listener.onEvent(delivered) }
        } catch (e: RejectedExecutionException) {
            if (refusalLogged.compareAndSet(false, true)) {
                log.warn(
                    "listener {} gets no more events: {} (each one refused goes to the tree's listener failure handler)",
                    listener,
                    e.message,
                )
            }
            throw e
        }
    }

    private companion object {
        val log = LoggerFactory.getLogger(JavaListenerCall::class.java)
    }
}
