package org.rtcoord.internal

import java.io.InputStream
import java.nio.ByteBuffer
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test

/**
 * [InboundConnection] read step by step on the test's thread, as JacORB's reader reads: a 12-byte header, then the body
 * in as many reads as the bytes come in, then the next header once the message is handed on. The bytes "in the socket"
 * are those given to [Arrivals].
 */
class InboundConnectionTest {
    /** A socket's input whose bytes arrive when the test says so; it never blocks. */
    private class Arrivals : InputStream() {
        private val bytes = ArrayDeque<Byte>()

        fun arrive(data: ByteArray) = data.forEach(bytes::addLast)

        override fun read(): Int = bytes.removeFirstOrNull()?.toInt()?.and(0xff) ?: -1

        override fun read(b: ByteArray, off: Int, len: Int): Int {
            val n = minOf(len, bytes.size)
            repeat(n) { b[off + it] = bytes.removeFirst() }
            return n
        }

        override fun available(): Int = bytes.size
    }

    private val socket = Arrivals()
    private val connection = InboundConnection(socket)
    private var passed = 0
    private val barrier by lazy { InboundConnection.Barrier(1) { passed++ } }

    @Test
    fun `a message is handled once the reader comes back for the next header, not when it reads on inside it`() {
        socket.arrive(message(1) + message(2).copyOf(14))
        read(12)
        read(24)
        // Message 1 read, not handed on; message 2 partly here.
        val target = connection.target()
        assertEquals(36L + 14, target)
        connection.await(target!!, barrier)
        assertFalse(barrier.setUp())

        read(12)
        assertEquals(0, passed, "message 2 is not here whole")
        assertEquals(2, read(24))
        socket.arrive(message(2).copyOfRange(14, 36))
        // The rest of its body: a read that starts inside a message hands nothing on.
        assertEquals(22, read(22))
        assertEquals(0, passed, "message 2 is read, not handed on")

        socket.arrive(message(3))
        read(12)
        assertEquals(1, passed, "message 2 handed on: the reader came back for message 3")
    }

    @Test
    fun `a connection with nothing unread and its reader back for more has nothing to wait for`() {
        socket.arrive(message(1))
        read(12)
        read(24)
        read(12)
        assertNull(connection.target())
    }

    @Test
    fun `closing it lets every wait go`() {
        socket.arrive(message(1))
        connection.await(connection.target()!!, barrier)
        assertFalse(barrier.setUp())
        connection.release()
        assertEquals(1, passed)
        assertNull(connection.target())
    }

    private fun read(length: Int): Int = connection.read(ByteArray(length), 0, length)

    /** A GIOP 1.2 request with a 24-byte body starting with [id], big-endian. */
    private fun message(id: Int): ByteArray =
        ByteBuffer.allocate(36)
            .put("GIOP".toByteArray())
            .put(1)
            .put(2)
            .put(0)
            .put(0)
            .putInt(24)
            .put(id.toByte())
            .array()
}
