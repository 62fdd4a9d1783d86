package org.rtcoord.internal.logs

import java.io.IOException
import java.net.InetSocketAddress
import java.nio.ByteBuffer
import java.nio.channels.SelectionKey
import java.nio.channels.SocketChannel
import java.time.Instant
import org.msgpack.core.MessagePack
import org.msgpack.core.MessagePackException
import org.msgpack.core.buffer.ArrayBufferInput

/**
 * One sender's TCP connection, read without blocking when its input's selector finds bytes for it: the handshake when a
 * key is set, then frames, each decoded once it has arrived whole ([FrameExtent]), its events handed to [received] in
 * order and its acknowledgement written after them.
 *
 * The bytes of a frame not yet whole wait in the connection, at most [ForwardSettings.maxRecordBytes] of them; answers
 * the sender does not read wait too, and while more than [MAX_UNSENT] bytes of them do the connection is not read from.
 * What the sender does wrong ends the connection with one call of [refused], naming it; nothing it does reaches another
 * connection. Not thread-safe: its input's selector thread owns it.
 *
 * @property key the connection's registration with the input's selector; its channel is the connection's.
 */
internal class ForwardConnection(
    private val key: SelectionKey,
    private val settings: ForwardSettings,
    private val handshake: SharedKeyHandshake?,
    private val received: (ForwardEntry) -> Unit,
    private val refused: (InetSocketAddress, ForwardRefusal, String) -> Unit,
) {
    private val channel = key.channel() as SocketChannel

    /** Who sent the connection's events. */
    val sender = channel.remoteAddress as InetSocketAddress

    private val frames = ForwardFrames(settings.maxRecordBytes)
    private val rate = EntryRate(settings.maxEntriesPerSecond)
    private val extent = FrameExtent(settings.maxRecordBytes)
    private val input = ArrayBufferInput(ByteArray(0))
    private val unpacker = MessagePack.newDefaultUnpacker(input)
    private val values = BoundedValues(unpacker, settings.maxRecordBytes, "a frame")
    private val packer = MessagePack.newDefaultBufferPacker()
    private val unsent = ArrayDeque<ByteBuffer>()
    private var unsentBytes = 0
    private var authenticated = handshake == null

    /** The bytes of a frame begun and not yet whole, or null between frames. */
    private var partial: ByteArray? = null

    /** When the frame in [partial] began (System.nanoTime); meaningless while [partial] is null. */
    private var frameBegun = 0L

    /** Whether the connection is still served: false once closed, for whatever reason. */
    private var isOpen = true

    /** Sends HELO when a key is set: the sender's first frame is then its PING. */
    fun start() {
        if (handshake == null) return
        handshake.helo(packer)
        send()
    }

    /**
     * Reads what has arrived (at most [READ_CHUNK] bytes) and hands on the frames now whole. [scratch] gives a buffer
     * of at least the size asked, shared by the input's connections. Returns whether the sender should be read again
     * without the input's rest: its read filled the chunk (more is waiting), or it was answered (a sender that asks for
     * acknowledgements waits for each before it sends more).
     */
    fun readable(scratch: (Int) -> ByteArray): Boolean =
        try {
            read(scratch)
        } catch (e: RefusedInput) {
            refuse(e.refusal, e.message)
            false
        } catch (e: MessagePackException) {
            refuse(ForwardRefusal.MALFORMED, "not MessagePack: ${e.message}")
            false
        } catch (e: IOException) {
            // Reset by the sender: a frame it left unfinished is a frame cut short.
            ended(e)
            false
        }

    /** Writes the answers waiting for the sender. */
    fun writable() {
        try {
            send()
        } catch (e: IOException) {
            close()
        }
    }

    /** Refuses the frame begun if it has not arrived whole within the frame timeout by [now] (System.nanoTime). */
    fun closeIfStalled(now: Long) {
        if (partial != null && now - frameBegun >= settings.frameTimeout.inWholeNanoseconds) {
            refuse(ForwardRefusal.INCOMPLETE_FRAME, "a frame begun was not complete within ${settings.frameTimeout}")
        }
    }

    /** When the frame begun must be whole by (System.nanoTime), or null when none is begun. */
    fun frameDeadline(): Long? = if (partial != null) frameBegun + settings.frameTimeout.inWholeNanoseconds else null

    /** Closes the connection without a word to anyone: the input is closing, or the sender went between frames. */
    fun close() {
        isOpen = false
        key.cancel()
        channel.close()
    }

    private fun read(scratch: (Int) -> ByteArray): Boolean {
        val kept = partial?.size ?: 0
        val buffer = scratch(kept + READ_CHUNK)
        partial?.copyInto(buffer)
        val count = channel.read(ByteBuffer.wrap(buffer, kept, READ_CHUNK))
        if (count < 0) {
            ended(null)
            return false
        }
        val length = kept + count
        val used = frames(buffer, length)
        val answered = send()
        if (!isOpen) return false
        partial = if (used == length) null else buffer.copyOfRange(used, length)
        // A frame that began in this read began now; one still arriving keeps the time it began.
        if (partial != null && (used > 0 || kept == 0)) frameBegun = System.nanoTime()
        return count == READ_CHUNK || answered
    }

    /**
     * Decodes and hands on every frame whole in [buffer]'s first [length] bytes, packing their answers to be sent in
     * one write; returns how many bytes they took.
     */
    private fun frames(buffer: ByteArray, length: Int): Int {
        var used = 0
        while (isOpen && used < length) {
            val size = extent.lengthOf(buffer, used, length - used)
            if (size < 0) break
            input.reset(buffer, used, size)
            unpacker.reset(input)
            values.begin()
            if (authenticated) {
                frames.read(values, ::deliver)?.let(::ack)
            } else {
                // Throws after a refusing PONG, which is sent before the connection closes.
                handshake!!.ping(values, packer)
                authenticated = true
            }
            used += size
        }
        return used
    }

    private fun deliver(tag: String, time: Instant, record: Map<String, Any?>) {
        if (!rate.admit()) {
            throw RefusedInput(ForwardRefusal.FLOOD, "more than ${settings.maxEntriesPerSecond} entries in a second")
        }
        received(ForwardEntry(tag, time, record, sender))
    }

    private fun ack(chunk: String) {
        packer.packMapHeader(1).packString("ack").packString(chunk)
    }

    /**
     * Hands what [packer] holds to the sender, as much as it takes now; the rest waits for the channel. Returns whether
     * [packer] held anything: the sender was answered.
     */
    private fun send(): Boolean {
        // What is packed reaches the packer's buffer on a flush.
        packer.flush()
        val answered = packer.bufferSize > 0
        if (answered) {
            val bytes = packer.toByteArray()
            packer.clear()
            unsent.addLast(ByteBuffer.wrap(bytes))
            unsentBytes += bytes.size
        } else if (unsent.isEmpty()) {
            return false
        }
        while (unsent.isNotEmpty()) {
            val first = unsent.first()
            unsentBytes -= channel.write(first)
            if (first.hasRemaining()) break
            unsent.removeFirst()
        }
        if (!isOpen) return answered
        key.interestOps(
            when {
                unsent.isEmpty() -> SelectionKey.OP_READ
                // A sender that does not read its answers is not read from until it does.
                unsentBytes > MAX_UNSENT -> SelectionKey.OP_WRITE
                else -> SelectionKey.OP_READ or SelectionKey.OP_WRITE
            }
        )
        return answered
    }

    /** The sender closed, or reset, the connection: refused when it did so in the middle of a frame. */
    private fun ended(e: IOException?) {
        if (partial != null) {
            val why = e?.let { " (${it.javaClass.simpleName})" } ?: ""
            refuse(ForwardRefusal.INCOMPLETE_FRAME, "the connection ended in the middle of a frame$why")
        } else {
            close()
        }
    }

    /** Sends what answers wait (a refusing PONG), says why the connection is refused, and closes it. */
    private fun refuse(refusal: ForwardRefusal, reason: String) {
        if (!isOpen) return
        try {
            send()
        } catch (e: IOException) {
            // The sender is gone: the refusal is still counted and said.
        }
        close()
        refused(sender, refusal, reason)
    }

    private companion object {
        /** The most read at once: a sender with more waiting is read again without the input's rest. */
        const val READ_CHUNK = 64 * 1024

        /** The most answers kept for a sender that does not read them before it is no longer read from. */
        const val MAX_UNSENT = 64 * 1024
    }
}
