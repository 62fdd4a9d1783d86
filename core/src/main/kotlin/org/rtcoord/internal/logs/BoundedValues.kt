package org.rtcoord.internal.logs

import java.math.BigInteger
import java.nio.ByteBuffer
import java.time.DateTimeException
import java.time.Instant
import org.msgpack.core.MessageFormat
import org.msgpack.core.MessageUnpacker
import org.msgpack.value.ValueType

/**
 * Reads MessagePack values from [unpacker] into Kotlin values, refusing a value (a frame, or one packed entry) that
 * takes more than [limit] bytes from [begin].
 *
 * msgpack-core's own `unpackValue` trusts the sizes a header declares (a `bin 32` header makes it allocate up to 4 GiB
 * before a byte of it arrived) and recurses once per level of nesting; neither is safe on a socket anyone can write to.
 * Here every payload is checked against what is left of the budget before it is read, arrays and maps grow as their
 * elements arrive rather than to their declared size, and nesting is bounded: what a sender can make a connection hold
 * is [limit] bytes and the values decoded from them.
 *
 * @property what names the unit in a refusal's reason: "a frame", "a packed entry".
 */
internal class BoundedValues(private val unpacker: MessageUnpacker, private val limit: Int, private val what: String) {
    private var start = 0L

    /** Starts a new unit: its bytes are counted from here. */
    fun begin() {
        start = unpacker.totalReadBytes
    }

    /** The type of the next value, read from its first byte. */
    fun nextType(): ValueType = unpacker.nextFormat.valueType

    /** Reads the next value: String, Long, Double, Boolean, ByteArray, List, Map or null. */
    fun value(): Any? = value(0)

    /** Reads a str or a bin as text, UTF-8 (fluent-logger-python sends strings as either, depending on its version). */
    fun text(name: String): String = String(raw(name), Charsets.UTF_8)

    /** Reads the bytes of a str or a bin. */
    fun raw(name: String): ByteArray {
        val size =
            when (nextType()) {
                ValueType.STRING -> unpacker.unpackRawStringHeader()
                ValueType.BINARY -> unpacker.unpackBinaryHeader()
                else -> throw malformed("$name is a string or bytes, not ${describeNext()}")
            }
        reserve(size)
        return unpacker.readPayload(size)
    }

    /** Reads an array's header and returns its size. */
    fun arrayHeader(name: String): Int {
        if (nextType() != ValueType.ARRAY) throw malformed("$name is an array, not ${describeNext()}")
        return unpacker.unpackArrayHeader()
    }

    /** Reads a map with text keys (see [value] for the values). */
    fun map(name: String): Map<String, Any?> {
        if (nextType() != ValueType.MAP) throw malformed("$name is a map, not ${describeNext()}")
        return map(0)
    }

    /** Reads a nil. */
    fun nil() = unpacker.unpackNil()

    /**
     * Reads an event's time: integer or float seconds, an EventTime (extension type 0: seconds and nanoseconds, each
     * four bytes big-endian), MessagePack's own timestamp (extension type -1), or Fluent Bit 2.1's `[time, metadata]`,
     * whose metadata is dropped. Null for nil or 0, which in_forward takes as "now".
     */
    fun time(): Instant? = time(nested = false)

    /** A [RefusedInput] of [ForwardRefusal.MALFORMED]. */
    fun malformed(reason: String) = RefusedInput(ForwardRefusal.MALFORMED, reason)

    /** What the next value is, for a reason. */
    private fun describeNext(): String = nextType().name.lowercase()

    private fun time(nested: Boolean): Instant? =
        try {
            when (nextType()) {
                ValueType.NIL -> null.also { nil() }
                ValueType.INTEGER -> unpacker.unpackLong().takeIf { it != 0L }?.let(Instant::ofEpochSecond)
                ValueType.FLOAT -> {
                    val seconds = unpacker.unpackDouble()
                    if (!seconds.isFinite()) throw malformed("the time is $seconds")
                    val whole = Math.floor(seconds)
                    Instant.ofEpochSecond(whole.toLong(), ((seconds - whole) * NANOS_PER_SECOND).toLong()).takeIf {
                        seconds != 0.0
                    }
                }
                ValueType.EXTENSION -> {
                    val header = unpacker.unpackExtensionTypeHeader()
                    when {
                        header.type == EVENT_TIME && header.length == EVENT_TIME_BYTES -> {
                            val data = ByteBuffer.wrap(unpacker.readPayload(EVENT_TIME_BYTES))
                            val seconds = data.int.toUInt().toLong()
                            val nanos = data.int.toUInt().toLong()
                            if (nanos >= NANOS_PER_SECOND) throw malformed("an EventTime's nanoseconds are $nanos")
                            Instant.ofEpochSecond(seconds, nanos).takeIf { seconds != 0L || nanos != 0L }
                        }
                        header.isTimestampType -> unpacker.unpackTimestamp(header)
                        else -> throw malformed("the time is an extension of type ${header.type}")
                    }
                }
                ValueType.ARRAY -> {
                    if (nested) throw malformed("the time is an array in an array")
                    val size = unpacker.unpackArrayHeader()
                    if (size < 1) throw malformed("the time is an empty array")
                    time(nested = true).also { repeat(size - 1) { value(1) } }
                }
                else -> throw malformed("the time is ${describeNext()}")
            }
        } catch (e: DateTimeException) {
            throw malformed("the time is out of range: ${e.message}")
        }

    private fun value(depth: Int): Any? {
        val format = unpacker.nextFormat
        return when (format.valueType) {
            ValueType.NIL -> null.also { nil() }
            ValueType.BOOLEAN -> unpacker.unpackBoolean()
            ValueType.INTEGER ->
                if (format == MessageFormat.UINT64) unpacker.unpackBigInteger().let(::integer)
                else unpacker.unpackLong()
            ValueType.FLOAT -> unpacker.unpackDouble()
            ValueType.STRING -> text("a string")
            ValueType.BINARY -> raw("bytes")
            ValueType.ARRAY -> {
                nest(depth)
                val size = unpacker.unpackArrayHeader()
                // Grown as elements arrive: the declared size is the sender's word, the bytes are not.
                val list = ArrayList<Any?>(minOf(size, INITIAL_CAPACITY))
                repeat(size) {
                    list += value(depth + 1)
                    checkUsed()
                }
                list
            }
            ValueType.MAP -> {
                nest(depth)
                map(depth)
            }
            ValueType.EXTENSION -> {
                val header = unpacker.unpackExtensionTypeHeader()
                reserve(header.length)
                unpacker.readPayload(header.length)
            }
        }
    }

    private fun map(depth: Int): Map<String, Any?> {
        val size = unpacker.unpackMapHeader()
        val map = LinkedHashMap<String, Any?>(minOf(size, INITIAL_CAPACITY))
        repeat(size) {
            val key =
                when (nextType()) {
                    ValueType.STRING,
                    ValueType.BINARY -> text("a key")
                    // Python's logging may carry dicts with number keys in a record's extras: kept, as text.
                    ValueType.NIL,
                    ValueType.BOOLEAN,
                    ValueType.INTEGER,
                    ValueType.FLOAT -> value(depth + 1).toString()
                    else -> throw malformed("a map's key is ${describeNext()}")
                }
            map[key] = value(depth + 1)
            checkUsed()
        }
        return map
    }

    private fun nest(depth: Int) {
        if (depth >= MAX_DEPTH) throw malformed("values nested deeper than $MAX_DEPTH levels")
    }

    private fun reserve(bytes: Int) {
        if (unpacker.totalReadBytes - start + bytes > limit) throw tooLarge()
    }

    /** Refuses the unit once it has taken more than its budget: called after each element, entry or record. */
    fun checkUsed() {
        if (unpacker.totalReadBytes - start > limit) throw tooLarge()
    }

    private fun tooLarge() = RefusedInput(ForwardRefusal.TOO_LARGE, "$what over $limit bytes")

    private fun integer(value: BigInteger): Any =
        if (value.bitLength() < Long.SIZE_BITS) value.toLong() else value.toDouble()

    private companion object {
        const val EVENT_TIME: Byte = 0
        const val EVENT_TIME_BYTES = 8
        const val NANOS_PER_SECOND = 1_000_000_000L
        const val MAX_DEPTH = 64
        const val INITIAL_CAPACITY = 16
    }
}
