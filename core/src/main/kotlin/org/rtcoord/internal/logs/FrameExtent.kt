package org.rtcoord.internal.logs

import org.msgpack.core.MessageInsufficientBufferException
import org.msgpack.core.MessagePack
import org.msgpack.core.buffer.ArrayBufferInput
import org.msgpack.value.ValueType

/**
 * Finds where the MessagePack value at the start of some bytes ends, so that a frame is decoded only once it has
 * arrived whole: a frame decoded as it arrives would hand on part of its events before it turned out cut short.
 *
 * Only headers are read; payloads are stepped over, not copied, so looking again each time more bytes arrive costs
 * little. Each declared size is checked against [limit] before its bytes are waited for: a header declaring 2 GiB is
 * refused at once, as [BoundedValues] refuses it, not after a frame timeout. Not thread-safe.
 *
 * @property limit the most a frame may take.
 */
internal class FrameExtent(private val limit: Int) {
    private val input = ArrayBufferInput(ByteArray(0))
    private val unpacker = MessagePack.newDefaultUnpacker(input)

    /**
     * The length of the value that starts at [offset] in [bytes] when all [length] of its bytes that follow hold it
     * whole; -1 when more are needed. Throws a [RefusedInput] of [ForwardRefusal.TOO_LARGE] for a value over [limit]
     * bytes, and msgpack-core's exception for bytes that are not MessagePack.
     */
    fun lengthOf(bytes: ByteArray, offset: Int, length: Int): Int {
        input.reset(bytes, offset, length)
        unpacker.reset(input)
        var values = 1L
        try {
            while (values > 0) {
                values--
                when (unpacker.nextFormat.valueType) {
                    ValueType.ARRAY -> values += unpacker.unpackArrayHeader()
                    ValueType.MAP -> values += 2L * unpacker.unpackMapHeader()
                    ValueType.STRING -> if (!skip(unpacker.unpackRawStringHeader(), length)) return -1
                    ValueType.BINARY -> if (!skip(unpacker.unpackBinaryHeader(), length)) return -1
                    ValueType.EXTENSION -> if (!skip(unpacker.unpackExtensionTypeHeader().length, length)) return -1
                    else -> unpacker.skipValue()
                }
                if (unpacker.totalReadBytes > limit) throw tooLarge()
            }
        } catch (e: MessageInsufficientBufferException) {
            return -1
        }
        return unpacker.totalReadBytes.toInt()
    }

    /** Steps over a payload of [size] bytes; false when they have not all arrived. */
    private fun skip(size: Int, length: Int): Boolean {
        val read = unpacker.totalReadBytes
        // A size over Int.MAX_VALUE comes as a negative Int from msgpack-core.
        if (size < 0 || read + size > limit) throw tooLarge()
        if (read + size > length) return false
        // A reference into the bytes, not a copy: they are all in the one buffer.
        unpacker.readPayloadAsReference(size)
        return true
    }

    private fun tooLarge() = RefusedInput(ForwardRefusal.TOO_LARGE, "a frame over $limit bytes")
}
