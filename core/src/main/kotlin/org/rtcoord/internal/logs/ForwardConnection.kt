package org.rtcoord.internal.logs

import java.io.BufferedOutputStream
import java.io.EOFException
import java.io.IOException
import java.net.InetSocketAddress
import java.net.Socket
import java.time.Instant
import kotlin.time.Duration.Companion.nanoseconds
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.filterNotNull
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import org.msgpack.core.MessageInsufficientBufferException
import org.msgpack.core.MessagePack
import org.msgpack.core.MessagePackException
import org.msgpack.core.MessagePacker
import org.msgpack.core.MessageUnpacker

/**
 * One sender's TCP connection: the handshake when a key is set, then frames until the sender closes, each frame's
 * events handed to [received] in order, and its acknowledgement written after them.
 *
 * Reads block, on the input's I/O threads; closing [socket] ends them, which is how [ForwardInput.close] and the frame
 * timeout stop a connection. What the sender does wrong ends the connection with one call of [refused]; nothing it does
 * reaches another connection.
 */
internal class ForwardConnection(
    private val socket: Socket,
    private val settings: ForwardSettings,
    private val handshake: SharedKeyHandshake?,
    private val received: (ForwardEntry) -> Unit,
    private val refused: (ForwardRefusal, String) -> Unit,
) {
    private val sender = socket.remoteSocketAddress as InetSocketAddress
    private val frames = ForwardFrames(settings.maxRecordBytes)
    private val rate = EntryRate(settings.maxEntriesPerSecond)

    /** When the frame being read began (System.nanoTime), or null between frames. */
    private val frameBegun = MutableStateFlow<Long?>(null)

    @Volatile private var timedOut = false

    /** Serves the connection until the sender closes it, it is refused, or the coroutine is cancelled. */
    suspend fun serve() {
        try {
            coroutineScope {
                val watchdog = launch { closeStalledFrames() }
                try {
                    read()
                } finally {
                    watchdog.cancel()
                }
            }
        } catch (e: RefusedInput) {
            refused(e.refusal, e.message)
        } catch (e: MessageInsufficientBufferException) {
            cut(e)
        } catch (e: EOFException) {
            cut(e)
        } catch (e: MessagePackException) {
            if (timedOut) cut(e) else refused(ForwardRefusal.MALFORMED, "not MessagePack: ${e.message}")
        } catch (e: IOException) {
            // A socket closed under a read: by close() (the coroutine is cancelled), the watchdog, or the sender.
            if (currentCoroutineContext().isActive && (timedOut || frameBegun.value != null)) cut(e)
        } finally {
            socket.close()
        }
    }

    /** Reports a frame that did not arrive whole, unless the input is closing. */
    private suspend fun cut(e: Exception) {
        if (!currentCoroutineContext().isActive) return
        val why =
            if (timedOut) "a frame begun was not complete within ${settings.frameTimeout}"
            else "the connection ended in the middle of a frame (${e.javaClass.simpleName})"
        refused(ForwardRefusal.INCOMPLETE_FRAME, why)
    }

    private fun read() {
        val unpacker = MessagePack.newDefaultUnpacker(socket.getInputStream())
        val packer = MessagePack.newDefaultPacker(BufferedOutputStream(socket.getOutputStream()))
        val values = BoundedValues(unpacker, settings.maxRecordBytes, "a frame")
        if (handshake != null) {
            handshake.helo(packer)
            if (!frame(unpacker, values) { handshake.ping(values, packer) }) return
        }
        while (true) {
            var chunk: String? = null
            if (!frame(unpacker, values) { chunk = frames.read(values, ::deliver) }) return
            // Written once the frame is over: a sender gone before its ack is not a frame cut short.
            chunk?.let { ack(packer, it) }
        }
    }

    /**
     * Reads one frame with [read] once its first byte is there, under the frame timeout's watch; false when the sender
     * closed between frames.
     */
    private inline fun frame(unpacker: MessageUnpacker, values: BoundedValues, read: () -> Unit): Boolean {
        if (!unpacker.hasNext()) return false
        frameBegun.value = System.nanoTime()
        values.begin()
        read()
        frameBegun.value = null
        return true
    }

    private fun deliver(tag: String, time: Instant, record: Map<String, Any?>) {
        if (!rate.admit()) {
            throw RefusedInput(ForwardRefusal.FLOOD, "more than ${settings.maxEntriesPerSecond} entries in a second")
        }
        received(ForwardEntry(tag, time, record, sender))
    }

    private fun ack(packer: MessagePacker, chunk: String) {
        packer.packMapHeader(1).packString("ack").packString(chunk)
        packer.flush()
    }

    /**
     * Closes the socket when a frame stays incomplete for the frame timeout: the blocked read then fails. One wait per
     * timeout at most, however many frames pass meanwhile: a frame begun at the time waited on and still being read
     * after it is late.
     */
    private suspend fun closeStalledFrames() {
        while (true) {
            val begun = frameBegun.filterNotNull().first()
            delay(settings.frameTimeout - (System.nanoTime() - begun).nanoseconds)
            if (frameBegun.value == begun) {
                timedOut = true
                socket.close()
                return
            }
        }
    }
}
