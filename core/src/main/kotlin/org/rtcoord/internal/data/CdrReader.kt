package org.rtcoord.internal.data

import java.nio.ByteBuffer
import java.nio.ByteOrder

/**
 * Reads CDR as OpenRTM's `corba_cdr` transport sends a sample: no encapsulation header, each value
 * aligned to its size counted from the first byte, in the connector's byte [order].
 */
internal class CdrReader(data: ByteArray, order: ByteOrder) {
    private val buffer = ByteBuffer.wrap(data).order(order)

    private fun align(size: Int) {
        val padding = (size - buffer.position() % size) % size
        require(buffer.remaining() >= padding + size) { "the data ends early, at byte ${buffer.position()}" }
        buffer.position(buffer.position() + padding)
    }

    fun boolean(): Boolean = octet() != 0.toByte()
    fun octet(): Byte { align(1); return buffer.get() }
    fun short(): Short { align(2); return buffer.short }
    fun long(): Int { align(4); return buffer.int }
    fun ulong(): Long = long().toLong() and 0xffffffffL
    fun float(): Float { align(4); return buffer.float }
    fun double(): Double { align(8); return buffer.double }

    /** A sequence's length, checked against what is left, so a bad length cannot allocate gigabytes. */
    fun length(elementSize: Int): Int {
        val length = ulong()
        require(length * elementSize <= buffer.remaining()) { "a sequence of $length elements exceeds the data" }
        return length.toInt()
    }

    fun string(): String {
        val length = length(1)
        require(length > 0) { "a string without its terminating NUL" }
        val bytes = ByteArray(length - 1).also(buffer::get)
        buffer.get()
        return String(bytes, Charsets.UTF_8)
    }

    /** Whether every byte was read (padding aside). */
    val exhausted: Boolean get() = !buffer.hasRemaining()
}
