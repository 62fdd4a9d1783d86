package org.rtcoord.runtime

import java.util.concurrent.CountDownLatch
import java.util.concurrent.atomic.AtomicInteger

/** Holds incoming calls while closed: a servant that hangs, never replying until it is opened again. */
internal class Gate {
    @Volatile private var latch: CountDownLatch? = null
    private val waiting = AtomicInteger()

    /** How many calls it holds now. */
    val held: Int
        get() = waiting.get()

    val isClosed: Boolean
        get() = latch != null

    fun close() {
        if (latch == null) latch = CountDownLatch(1)
    }

    fun open() {
        latch?.countDown()
        latch = null
    }

    /** Blocks the calling request thread while the gate is closed. */
    fun pass() {
        val closed = latch ?: return
        waiting.incrementAndGet()
        try {
            closed.await()
        } finally {
            waiting.decrementAndGet()
        }
    }
}
