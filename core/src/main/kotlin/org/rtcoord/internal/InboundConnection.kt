package org.rtcoord.internal

import java.io.IOException
import java.io.InputStream
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration
import org.jacorb.orb.giop.Messages

/**
 * What the ORB has read of one connection a peer opened to it, counted in the stream it reads from: how many bytes it
 * took ([consumed]), and up to where it had handled every message when it last came back for the next one ([handled]).
 * JacORB's reader takes each GIOP message's 12-byte header, then exactly its body, and hands the message to its POA
 * before it reads again; so a read that starts where a message ends means that message is in the POA's queue.
 */
internal class InboundConnection(private val input: InputStream) : InputStream() {
    /** Waits until [handled] reaches [target] for a [Barrier]. */
    private class Wait(val target: Long, val barrier: Barrier)

    @Volatile private var consumed = 0L
    @Volatile private var handled = 0L
    @Volatile private var closed = false
    private val header = ByteArray(GIOP_HEADER)
    private var headerFill = 0
    private var bodyLeft = 0L
    /** Framing was lost (not GIOP): nothing can be told of this connection, and nobody waits for it. */
    @Volatile private var unframed = false
    private val waits = ConcurrentLinkedQueue<Wait>()
    /** The reader found the connection closed: it will not read again, nor hand the POAs anything more. */
    private val readerGone = CountDownLatch(1)

    /**
     * Where [handled] must come for every byte this connection holds now, read or not, to have been handled; null when
     * it has been already. Counted twice around the kernel's count, so that a read that ended in between is not counted
     * half.
     */
    fun target(): Long? {
        if (closed || unframed) return null
        fun unread(): Int? =
            try {
                input.available()
            } catch (e: IOException) {
                null
            }
        repeat(SNAPSHOT_TRIES) {
            val before = consumed
            val waiting = unread() ?: return null
            if (consumed == before) return (before + waiting).takeIf { it > handled }
        }
        // Read all along. Counted the other way round, a read ending in between is counted twice rather
        // than not at all: waiting for a little more than was there ends with the next message it reads.
        val waiting = unread() ?: return null
        return (consumed + waiting).takeIf { it > handled }
    }

    /** Has [barrier] wait until this connection has handled up to [target], or closed. */
    fun await(target: Long, barrier: Barrier) {
        val wait = Wait(target, barrier)
        waits += wait
        // The reader may have passed the target, or the connection closed, while the wait was added.
        if ((handled >= target || closed || unframed) && waits.remove(wait)) barrier.arrive()
    }

    /** Waits up to [timeout] for the reader to find the connection closed; whether it has. */
    fun awaitReaderGone(timeout: Duration): Boolean = readerGone.await(timeout.inWholeNanoseconds, TimeUnit.NANOSECONDS)

    /** The connection is closed: nothing more will be handled, and nobody waits for it. */
    fun release() {
        closed = true
        releaseWaits()
    }

    override fun read(): Int {
        val one = ByteArray(1)
        return if (read(one, 0, 1) < 0) -1 else one[0].toInt() and 0xff
    }

    override fun read(b: ByteArray, off: Int, len: Int): Int {
        if (headerFill == 0 && bodyLeft == 0L) reached(consumed)
        val n =
            try {
                input.read(b, off, len)
            } catch (e: IOException) {
                ended()
                throw e
            }
        if (n < 0) ended() else take(b, off, n)
        return n
    }

    override fun available(): Int = input.available()

    override fun close() {
        release()
        input.close()
    }

    private fun ended() {
        release()
        readerGone.countDown()
    }

    private fun releaseWaits() {
        while (true) waits.poll()?.barrier?.arrive() ?: break
    }

    /** The reader came back for a message starting at [position]: every one before it is handled. */
    private fun reached(position: Long) {
        handled = position
        if (waits.isEmpty()) return
        for (wait in waits) if (wait.target <= position && waits.remove(wait)) wait.barrier.arrive()
    }

    /** Follows the GIOP framing through [n] bytes just read into [b] at [off]. */
    private fun take(b: ByteArray, off: Int, n: Int) {
        var i = off
        val end = off + n
        while (i < end && !unframed) {
            if (bodyLeft > 0) {
                val k = minOf(bodyLeft, (end - i).toLong()).toInt()
                bodyLeft -= k
                i += k
            } else {
                header[headerFill++] = b[i++]
                if (headerFill == GIOP_HEADER) {
                    headerFill = 0
                    bodyLeft = bodySize()
                    if (bodyLeft < 0) unframed = true
                }
            }
        }
        consumed += n
        if (unframed) releaseWaits()
    }

    /** The body size in the header just read, as JacORB reads it; negative when it is not a GIOP header. */
    private fun bodySize(): Long = if (Messages.matchGIOPMagic(header)) Messages.getMsgSize(header).toLong() else -1

    /**
     * Counts down the connections still to be handled up to their targets, and the one who set it up: [then] runs on
     * the thread of the last connection to arrive, unless every connection had arrived by the time every wait was
     * [setUp].
     */
    class Barrier(connections: Int, private val then: Runnable) {
        private val remaining = AtomicInteger(connections + 1)

        /** A connection arrived; the last one runs [then]. */
        fun arrive() {
            if (remaining.decrementAndGet() == 0) then.run()
        }

        /** Every wait is set up: whether every connection has arrived already, in which case [then] does not run. */
        fun setUp(): Boolean = remaining.decrementAndGet() == 0
    }

    private companion object {
        const val GIOP_HEADER = 12
        const val SNAPSHOT_TRIES = 3
    }
}
