package org.rtcoord.runtime

import java.nio.ByteBuffer
import java.nio.ByteOrder

/**
 * The data types runtime ports carry, with the CDR encoding OpenRTM's `corba_cdr` transport uses by
 * default: little-endian, no encapsulation header, aligned from the start of the buffer.
 */
public enum class DataType(public val repositoryId: String) {
    TIMED_LONG("IDL:RTC/TimedLong:1.0"),
    TIMED_DOUBLE("IDL:RTC/TimedDouble:1.0"),
    TIMED_DOUBLE_SEQ("IDL:RTC/TimedDoubleSeq:1.0"),
    TIMED_STRING("IDL:RTC/TimedString:1.0");

    /** Encodes [value] (Int, Double, DoubleArray or String, matching this type) stamped with [timeNanos]. */
    public fun encode(value: Any, timeNanos: Long): ByteArray {
        val out = CdrOut()
        out.ulong(timeNanos / 1_000_000_000)
        out.ulong(timeNanos % 1_000_000_000)
        when (this) {
            TIMED_LONG -> out.long(value as Int)
            TIMED_DOUBLE -> out.double(value as Double)
            TIMED_DOUBLE_SEQ -> (value as DoubleArray).let { array -> out.ulong(array.size.toLong()); array.forEach(out::double) }
            TIMED_STRING -> out.string(value as String)
        }
        return out.bytes()
    }

    /** Decodes a sample this type encoded; throws [IllegalArgumentException] on malformed data. */
    public fun decode(data: ByteArray): Sample {
        val input = CdrIn(data)
        val seconds = input.ulong()
        val nanos = input.ulong()
        val value: Any = when (this) {
            TIMED_LONG -> input.long()
            TIMED_DOUBLE -> input.double()
            TIMED_DOUBLE_SEQ -> DoubleArray(input.length(8)) { input.double() }
            TIMED_STRING -> input.string()
        }
        return Sample(seconds * 1_000_000_000 + nanos, value)
    }

    public companion object {
        /** The type with [repositoryId], or null. */
        public fun of(repositoryId: String): DataType? = values().firstOrNull { it.repositoryId == repositoryId }
    }
}

/** One value read from a port and the time stamp it was written with. */
public data class Sample(val timeNanos: Long, val value: Any)

private class CdrOut {
    private var buffer = ByteBuffer.allocate(64).order(ByteOrder.LITTLE_ENDIAN)

    private fun reserve(alignment: Int, size: Int) {
        val padding = (alignment - buffer.position() % alignment) % alignment
        if (buffer.remaining() < padding + size) {
            val grown = ByteBuffer.allocate((buffer.capacity() + padding + size) * 2).order(ByteOrder.LITTLE_ENDIAN)
            buffer.flip()
            grown.put(buffer)
            buffer = grown
        }
        repeat(padding) { buffer.put(0) }
    }

    fun ulong(value: Long) { reserve(4, 4); buffer.putInt(value.toInt()) }
    fun long(value: Int) { reserve(4, 4); buffer.putInt(value) }
    fun double(value: Double) { reserve(8, 8); buffer.putDouble(value) }
    fun string(value: String) {
        val utf8 = value.toByteArray(Charsets.UTF_8)
        ulong(utf8.size + 1L)
        reserve(1, utf8.size + 1)
        buffer.put(utf8).put(0)
    }

    fun bytes(): ByteArray = buffer.array().copyOf(buffer.position())
}

private class CdrIn(data: ByteArray) {
    private val buffer = ByteBuffer.wrap(data).order(ByteOrder.LITTLE_ENDIAN)

    private fun align(alignment: Int, size: Int) {
        val padding = (alignment - buffer.position() % alignment) % alignment
        require(buffer.remaining() >= padding + size) { "CDR data ends early at byte ${buffer.position()}" }
        buffer.position(buffer.position() + padding)
    }

    fun ulong(): Long { align(4, 4); return buffer.int.toLong() and 0xffffffffL }
    fun long(): Int { align(4, 4); return buffer.int }
    fun double(): Double { align(8, 8); return buffer.double }

    /** A sequence length, checked against what is left so a bad length cannot allocate gigabytes. */
    fun length(elementSize: Int): Int {
        val length = ulong()
        require(length * elementSize <= buffer.remaining()) { "CDR sequence of $length elements exceeds the data" }
        return length.toInt()
    }

    fun string(): String {
        val length = length(1)
        require(length > 0) { "CDR string without its terminating NUL" }
        val utf8 = ByteArray(length - 1).also(buffer::get)
        buffer.get()
        return String(utf8, Charsets.UTF_8)
    }
}
