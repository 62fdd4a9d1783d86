package org.rtcoord.internal.logs

import java.io.BufferedOutputStream
import java.io.IOException
import java.net.InetSocketAddress
import java.net.Socket
import java.net.SocketTimeoutException
import org.msgpack.core.MessagePack
import org.msgpack.core.MessagePacker
import org.msgpack.value.Value

/**
 * A forward-protocol sender of the tests' own, on msgpack-core, for what the real clients never send: Forward mode,
 * several gzip members, and every kind of bad input. Reads wait at most [deadlineMillis].
 */
internal class ForwardTestClient(address: InetSocketAddress, deadlineMillis: Int = 10_000) : AutoCloseable {
    val socket = Socket(address.address, address.port).apply { soTimeout = deadlineMillis }
    private val packer = MessagePack.newDefaultPacker(BufferedOutputStream(socket.getOutputStream()))
    private val unpacker = MessagePack.newDefaultUnpacker(socket.getInputStream())

    /** Packs with [write] and sends it at once. */
    fun send(write: MessagePacker.() -> Unit) {
        packer.write()
        packer.flush()
    }

    /** Sends [bytes] as they are. */
    fun sendRaw(bytes: ByteArray) {
        socket.getOutputStream().write(bytes)
        socket.getOutputStream().flush()
    }

    /**
     * Sends [bytes] that the server may refuse before it has read them all: its closing the connection then fails the
     * write (a broken pipe, a reset), which is what a refused sender sees.
     */
    fun sendUntilRefused(bytes: ByteArray) {
        try {
            sendRaw(bytes)
        } catch (e: IOException) {
            // Refused midway: the test reads why from the input.
        }
    }

    /** The next value the server sends. */
    fun receive(): Value = unpacker.unpackValue()

    /**
     * True once the server closed the connection (end of stream or reset), false if it is still open at the deadline.
     */
    fun closedByServer(): Boolean =
        try {
            socket.getInputStream().read() == -1
        } catch (e: SocketTimeoutException) {
            false
        } catch (e: IOException) {
            true
        }

    override fun close() = socket.close()
}

/** Packs a `[time, record]` entry of an integer time and a record of `message`. */
internal fun MessagePacker.entry(seconds: Long, message: String): MessagePacker =
    packArrayHeader(2).packLong(seconds).packMapHeader(1).packString("message").packString(message)

/** Packs an EventTime: extension type 0, seconds and nanoseconds. */
internal fun MessagePacker.eventTime(seconds: Int, nanos: Int): MessagePacker =
    packExtensionTypeHeader(0, 8).addPayload(java.nio.ByteBuffer.allocate(8).putInt(seconds).putInt(nanos).array())
