package org.rtcoord.internal

import java.io.DataInputStream
import java.io.EOFException
import java.net.InetAddress
import java.net.Socket
import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.CountDownLatch
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.Semaphore
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * [InboundConnections] over real loopback sockets, read as JacORB reads them: each GIOP header, then exactly its body,
 * then the message is handed on before the next read. The reader here hands each message to [handled] once the test
 * lets it ([handOn]), so a message can be held between read and hand-off, and tells what it holds ([holding]) and what
 * it skipped for not being GIOP ([skipped]).
 */
class InboundConnectionsTest {
    private val inbound = InboundConnections()
    private val listening = inbound.createServerSocket(0, 0, InetAddress.getLoopbackAddress())
    private val peer = Socket(listening.inetAddress, listening.localPort)
    private val handled = CopyOnWriteArrayList<Int>()
    private val handOn = Semaphore(0)
    private val holding = LinkedBlockingQueue<Int>()
    private val skipped = LinkedBlockingQueue<String>()
    private val readerEnded = CountDownLatch(1)
    private val reader = Thread {
        listening.accept().use { socket ->
            val input = DataInputStream(socket.getInputStream())
            try {
                while (true) {
                    val header = ByteArray(12).also(input::readFully)
                    // JacORB drops what does not start like a GIOP message and reads on.
                    if (String(header, 0, 4) != "GIOP") {
                        skipped += String(header)
                        continue
                    }
                    val order = if (header[6].toInt() and 1 == 1) ByteOrder.LITTLE_ENDIAN else ByteOrder.BIG_ENDIAN
                    val body = ByteArray(ByteBuffer.wrap(header, 8, 4).order(order).int).also(input::readFully)
                    holding += body[0].toInt()
                    handOn.acquire()
                    handled += body[0].toInt()
                }
            } catch (e: EOFException) {
                // The peer closed: the ORB closes its end, as JacORB does.
            } finally {
                readerEnded.countDown()
            }
        }
    }
        .apply {
            isDaemon = true
            start()
        }

    @AfterEach
    fun close() {
        peer.close()
        handOn.release(100)
        assertTrue(readerEnded.await(5, TimeUnit.SECONDS), "the reader ended")
        listening.close()
    }

    @Test
    fun `nothing received is nothing to wait for`() {
        assertTrue(inbound.allTaken { error("nothing to wait for") })
    }

    @Test
    fun `a message read but not handed on yet is waited for until the reader comes back for the next`() {
        send(message(1))
        val later = waitForAll()
        handOn.release()
        assertEquals(listOf(1), later.get(5, TimeUnit.SECONDS))
    }

    @Test
    fun `messages still in the socket are waited for, and those sent after them are not`() {
        send(message(1), message(2, littleEndian = true))
        val later = waitForAll()
        send(message(3))
        handOn.release(2)
        assertEquals(listOf(1, 2), later.get(5, TimeUnit.SECONDS))
        handOn.release()
    }

    @Test
    fun `a connection that closes before its reader got that far counts as done`() {
        // The second message is cut short: the reader waits for the rest of it until the peer closes.
        send(message(1), message(2).copyOf(14))
        val later = waitForAll()
        handOn.release()
        assertFalse(later.isDone, "waited before the close")
        peer.close()
        assertEquals(listOf(1), later.get(5, TimeUnit.SECONDS))
    }

    @Test
    fun `bytes that are not GIOP are nothing to wait for`() {
        // Twelve bytes make a header the reader skips; the last six wait for six more that never come.
        send("GET / HTTP/1.1\r\n\r\n".toByteArray())
        assertEquals("GET / HTTP/1", skipped.poll(5, TimeUnit.SECONDS))
        assertTrue(inbound.allTaken { error("nothing to wait for") })
    }

    /**
     * Asks once the reader holds the first message; the handed-on messages when [InboundConnections.allTaken] called
     * back.
     */
    private fun waitForAll(): CompletableFuture<List<Int>> {
        assertEquals(1, holding.poll(5, TimeUnit.SECONDS), "the reader holds the first message")
        val later = CompletableFuture<List<Int>>()
        assertFalse(inbound.allTaken { later.complete(handled.toList()) }, "something to wait for")
        return later
    }

    private fun send(vararg messages: ByteArray) {
        messages.forEach { peer.getOutputStream().write(it) }
        peer.getOutputStream().flush()
    }

    /** A GIOP 1.2 request whose body starts with [id]. */
    private fun message(id: Int, littleEndian: Boolean = false): ByteArray {
        val body = ByteArray(24) { if (it == 0) id.toByte() else 7 }
        val order = if (littleEndian) ByteOrder.LITTLE_ENDIAN else ByteOrder.BIG_ENDIAN
        return ByteBuffer.allocate(12 + body.size)
            .order(order)
            .put("GIOP".toByteArray())
            .put(1)
            .put(2)
            .put(if (littleEndian) 1 else 0)
            .put(0)
            .putInt(body.size)
            .put(body)
            .array()
    }
}
