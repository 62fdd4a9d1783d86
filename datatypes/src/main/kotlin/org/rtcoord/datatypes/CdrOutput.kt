package org.rtcoord.datatypes

import java.nio.ByteBuffer
import java.nio.ByteOrder

/**
 * Writes CDR as OpenRTM's `corba_cdr` transport sends a sample: no encapsulation header, each value aligned to its size
 * counted from the first byte, in the byte [order] the connector negotiated. [restart] makes it write the next sample
 * into the same buffer.
 */
internal class CdrOutput(private var order: ByteOrder, capacity: Int = 256) {
    private var buffer: ByteBuffer = ByteBuffer.allocate(capacity).order(order)

    /** Empties it for a sample in byte [order], keeping its buffer. */
    fun restart(order: ByteOrder) {
        this.order = order
        buffer.clear().order(order)
    }

    private fun reserve(alignment: Int, size: Int) {
        val padding = (alignment - buffer.position() % alignment) % alignment
        if (buffer.remaining() < padding + size) {
            val grown =
                ByteBuffer.allocate(maxOf(buffer.capacity() * 2, buffer.position() + padding + size)).order(order)
            buffer.flip()
            grown.put(buffer)
            buffer = grown
        }
        repeat(padding) { buffer.put(0) }
    }

    fun octet(value: Byte) {
        reserve(1, 1)
        buffer.put(value)
    }

    fun short(value: Short) {
        reserve(2, 2)
        buffer.putShort(value)
    }

    fun long(value: Int) {
        reserve(4, 4)
        buffer.putInt(value)
    }

    fun longLong(value: Long) {
        reserve(8, 8)
        buffer.putLong(value)
    }

    fun float(value: Float) {
        reserve(4, 4)
        buffer.putFloat(value)
    }

    fun double(value: Double) {
        reserve(8, 8)
        buffer.putDouble(value)
    }

    /** [count] doubles at once: a sequence's elements after its length. */
    fun doubles(values: DoubleArray) {
        reserve(8, 8 * values.size)
        buffer.asDoubleBuffer().put(values)
        buffer.position(buffer.position() + 8 * values.size)
    }

    fun octets(values: ByteArray) {
        reserve(1, values.size)
        buffer.put(values)
    }

    fun string(value: String) {
        val bytes = value.toByteArray(Charsets.UTF_8)
        long(bytes.size + 1)
        reserve(1, bytes.size + 1)
        buffer.put(bytes).put(0)
    }

    /** GIOP 1.2: the length in octets, then UTF-16 without a byte-order mark (so big-endian), no terminator. */
    fun wideString(value: String) {
        val bytes = value.toByteArray(Charsets.UTF_16BE)
        long(bytes.size)
        octets(bytes)
    }

    /** GIOP 1.2: one octet of length, then the character in UTF-16, big-endian. */
    fun wideChar(value: Char) {
        octet(2)
        octets(value.toString().toByteArray(Charsets.UTF_16BE))
    }

    fun bytes(): ByteArray = buffer.array().copyOf(buffer.position())
}
