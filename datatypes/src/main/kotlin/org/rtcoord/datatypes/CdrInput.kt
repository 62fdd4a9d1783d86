package org.rtcoord.datatypes

import java.nio.ByteBuffer
import java.nio.ByteOrder

/**
 * Reads what [CdrOutput] writes. A length that exceeds what is left, or data that ends early, throws
 * [IllegalArgumentException] naming the byte: a bad sample can never allocate gigabytes.
 */
internal class CdrInput(data: ByteArray, order: ByteOrder) {
    private val buffer = ByteBuffer.wrap(data).order(order)

    private fun align(size: Int) {
        val padding = (size - buffer.position() % size) % size
        require(buffer.remaining() >= padding + size) { "the data ends early, at byte ${buffer.position()}" }
        buffer.position(buffer.position() + padding)
    }

    fun octet(): Byte {
        align(1)
        return buffer.get()
    }

    fun short(): Short {
        align(2)
        return buffer.short
    }

    fun long(): Int {
        align(4)
        return buffer.int
    }

    fun longLong(): Long {
        align(8)
        return buffer.long
    }

    fun float(): Float {
        align(4)
        return buffer.float
    }

    fun double(): Double {
        align(8)
        return buffer.double
    }

    /** A sequence's length, checked against what is left given each element takes at least [minimumSize] bytes. */
    fun length(minimumSize: Int): Int {
        val length = long().toLong() and 0xffffffffL
        require(length * minimumSize <= buffer.remaining()) {
            "a sequence of $length elements exceeds the data, at byte ${buffer.position()}"
        }
        return length.toInt()
    }

    fun doubles(count: Int): DoubleArray {
        if (count == 0) return DoubleArray(0)
        align(8)
        return DoubleArray(count).also {
            buffer.asDoubleBuffer().get(it)
            buffer.position(buffer.position() + 8 * count)
        }
    }

    fun octets(count: Int): ByteArray {
        require(buffer.remaining() >= count) { "the data ends early, at byte ${buffer.position()}" }
        return ByteArray(count).also(buffer::get)
    }

    fun string(): String {
        val length = length(1)
        require(length > 0) { "a string without its terminating NUL, at byte ${buffer.position()}" }
        val bytes = octets(length - 1)
        require(buffer.get() == 0.toByte()) { "a string not terminated by NUL, at byte ${buffer.position() - 1}" }
        return String(bytes, Charsets.UTF_8)
    }

    fun wideString(): String = utf16(octets(length(1)))

    fun wideChar(): Char {
        val length = octet().toInt() and 0xff
        val text = utf16(octets(length))
        require(text.length == 1) { "a wide character of $length octets, at byte ${buffer.position()}" }
        return text[0]
    }

    /** UTF-16 as GIOP 1.2 sends it: big-endian unless a byte-order mark says otherwise. */
    private fun utf16(bytes: ByteArray): String = String(bytes, Charsets.UTF_16)

    /** Whether every byte was read. */
    val exhausted: Boolean
        get() = !buffer.hasRemaining()
}
