package org.rtcoord

import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** Collects events from a registration and hands them out in order, waiting with a deadline. */
class EventRecorder {
    val events = LinkedBlockingQueue<RtcEvent>()

    val handler: suspend (RtcEvent) -> Unit = { events += it }

    /** The next event of type [E], skipping others, within [timeout]. */
    inline fun <reified E : RtcEvent> next(timeout: Duration = 5.seconds, where: (E) -> Boolean = { true }): E {
        val deadline = System.nanoTime() + timeout.inWholeNanoseconds
        val skipped = mutableListOf<RtcEvent>()
        while (true) {
            val remaining = deadline - System.nanoTime()
            val event =
                events.poll(remaining.coerceAtLeast(0), TimeUnit.NANOSECONDS)
                    ?: throw AssertionError("no ${E::class.simpleName} within $timeout; skipped $skipped")
            if (event is E && where(event)) return event
            skipped += event
        }
    }

    /** The events of type [E] received so far (and still unread). */
    inline fun <reified E : RtcEvent> drained(): List<E> = generateSequence {
        events.poll()
    }
        .filterIsInstance<E>()
        .toList()
}
