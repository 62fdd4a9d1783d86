package org.rtcoord.runtime

import java.util.concurrent.CountDownLatch
import java.util.concurrent.atomic.AtomicInteger
import org.omg.CORBA.COMM_FAILURE
import org.omg.CORBA.CompletionStatus

/**
 * Holds incoming calls while closed: a servant that hangs, never replying until it is opened again, or until its
 * process [end]s.
 */
internal class Gate {
    @Volatile private var latch: CountDownLatch? = null
    @Volatile private var ended = false
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

    /**
     * Fails the calls it holds and every later one: their process is gone, and its ORB's shutdown would wait forever
     * for a request thread held here.
     */
    fun end() {
        ended = true
        latch?.countDown()
    }

    /** Blocks the calling request thread while the gate is closed. */
    fun pass() {
        checkNotEnded()
        val closed = latch ?: return
        waiting.incrementAndGet()
        try {
            closed.await()
        } finally {
            waiting.decrementAndGet()
        }
        checkNotEnded()
    }

    private fun checkNotEnded() {
        if (ended) throw COMM_FAILURE("the component's process has ended", 0, CompletionStatus.COMPLETED_NO)
    }
}
