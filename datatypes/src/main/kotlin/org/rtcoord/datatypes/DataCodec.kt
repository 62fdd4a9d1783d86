package org.rtcoord.datatypes

import java.math.BigInteger
import java.nio.ByteOrder
import java.util.concurrent.atomic.AtomicReference

/**
 * The CDR codec of one data type, as OpenRTM-aist's `corba_cdr` data ports send their samples: the value's CDR with no
 * encapsulation header (no byte-order octet: the connector's `dataport.serializer.cdr.endian` says the order), aligned
 * from the first byte. Values are those [IdlType] lists. The one codec for the samples rtcoord reads (core's taps) and
 * writes (the runtime's out-ports).
 */
public class DataCodec(public val type: IdlType) {
    /**
     * [value] as CDR in little-endian or big-endian order; throws [IllegalArgumentException] naming the member that
     * does not fit.
     */
    public fun encode(value: Any?, littleEndian: Boolean): ByteArray {
        val out = spare.getAndSet(null)?.apply { restart(order(littleEndian)) } ?: CdrOutput(order(littleEndian))
        try {
            write(out, type, value)
        } catch (e: Mismatch) {
            throw IllegalArgumentException("${type.name}${e.path}: ${e.reason}")
        }
        return out.bytes().also { spare.set(out) }
    }

    /**
     * A buffer grown to the size of the samples encoded so far, for the next one: a port's samples are alike, so at 100
     * Hz a scan is encoded without allocating and growing a buffer every 10 ms. Taken by one encoding at a time; one
     * that finds it taken makes its own.
     */
    private val spare = AtomicReference<CdrOutput?>()

    /**
     * The value [data] holds; throws [IllegalArgumentException] when it does not decode as this type, or holds bytes
     * after it.
     */
    public fun decode(data: ByteArray, littleEndian: Boolean): Any? {
        val input = CdrInput(data, order(littleEndian))
        val value = read(input, type)
        require(input.exhausted) { "${data.size} bytes hold more than one ${type.name}" }
        return value
    }

    private fun order(littleEndian: Boolean) = if (littleEndian) ByteOrder.LITTLE_ENDIAN else ByteOrder.BIG_ENDIAN

    /** Writes [value] as [type]; a value that does not fit throws [Mismatch], which each enclosing member names. */
    private fun write(out: CdrOutput, type: IdlType, value: Any?) {
        when (type) {
            is IdlType.Primitive -> writePrimitive(out, type, value)
            is IdlType.StringType -> {
                val text = value as? String ?: mismatch("a string", value)
                if (type.bound != 0 && text.length > type.bound)
                    throw Mismatch("${text.length} characters exceed the bound ${type.bound}")
                if (type.wide) out.wideString(text) else out.string(text)
            }
            is IdlType.Sequence -> {
                val elements = elements(value)
                if (type.bound != 0 && elements.size > type.bound)
                    throw Mismatch("${elements.size} elements exceed the bound ${type.bound}")
                out.long(elements.size)
                writeElements(out, type.element, elements)
            }
            is IdlType.ArrayType -> {
                val elements = elements(value)
                if (elements.size != type.length)
                    throw Mismatch("${elements.size} elements where the array holds ${type.length}")
                writeElements(out, type.element, elements)
            }
            is IdlType.Struct -> {
                val fields = value as? Map<*, *> ?: mismatch("a struct (a map of its members)", value)
                for (member in type.members) {
                    if (!fields.containsKey(member.name)) throw Mismatch("missing").under(".${member.name}")
                    member(member.name) { write(out, member.type, fields[member.name]) }
                }
            }
            is IdlType.Enum -> out.long(ordinal(type, value))
            is IdlType.Union -> {
                val fields = value as? Map<*, *> ?: mismatch("a union (a map with its discriminator)", value)
                val discriminator = fields[IdlType.UNION_DISCRIMINATOR]
                member(IdlType.UNION_DISCRIMINATOR) { write(out, type.discriminator, discriminator) }
                val case = type.caseFor(discriminatorKey(type.discriminator, discriminator)) ?: return
                member(case.name) { write(out, case.type, fields[case.name]) }
            }
            is IdlType.Alias -> write(out, type.type, value)
        }
    }

    private fun writeElements(out: CdrOutput, element: IdlType, elements: Elements) {
        val resolved = element.resolved
        when {
            resolved === IdlType.Primitive.DOUBLE && elements.doubles != null -> out.doubles(elements.doubles)
            resolved === IdlType.Primitive.OCTET && elements.octets != null -> out.octets(elements.octets)
            else ->
                for (index in 0 until elements.size) {
                    try {
                        write(out, element, elements[index])
                    } catch (e: Mismatch) {
                        throw e.under("[$index]")
                    }
                }
        }
    }

    /** Runs [write] for the member [name], naming it in a [Mismatch]: the path is built only for an error. */
    private inline fun member(name: String, write: () -> Unit) {
        try {
            write()
        } catch (e: Mismatch) {
            throw e.under(".$name")
        }
    }

    private fun writePrimitive(out: CdrOutput, type: IdlType.Primitive, value: Any?) {
        when (type) {
            IdlType.Primitive.BOOLEAN -> out.octet(if (value as? Boolean ?: mismatch("a boolean", value)) 1 else 0)
            IdlType.Primitive.CHAR -> out.octet(character(value).code.toByte())
            IdlType.Primitive.WCHAR -> out.wideChar(character(value))
            IdlType.Primitive.OCTET -> out.octet(number(value).toByte())
            IdlType.Primitive.SHORT,
            IdlType.Primitive.USHORT -> out.short(number(value).toShort())
            IdlType.Primitive.LONG,
            IdlType.Primitive.ULONG -> out.long(number(value).toLong().toInt())
            IdlType.Primitive.LONGLONG,
            IdlType.Primitive.ULONGLONG -> out.longLong(number(value).toLong())
            IdlType.Primitive.FLOAT -> out.float(number(value).toFloat())
            IdlType.Primitive.DOUBLE -> out.double(number(value).toDouble())
        }
    }

    private fun read(input: CdrInput, type: IdlType): Any? =
        when (type) {
            is IdlType.Primitive -> readPrimitive(input, type)
            is IdlType.StringType -> if (type.wide) input.wideString() else input.string()
            is IdlType.Sequence -> readElements(input, type.element, input.length(minimumSize(type.element)))
            is IdlType.ArrayType -> readElements(input, type.element, type.length)
            is IdlType.Struct ->
                LinkedHashMap<String, Any?>(type.members.size * 2).apply {
                    for (member in type.members) put(member.name, read(input, member.type))
                }
            is IdlType.Enum -> {
                val ordinal = input.long()
                require(ordinal in type.enumerators.indices) { "${type.name}: no enumerator $ordinal" }
                type.enumerators[ordinal]
            }
            is IdlType.Union -> {
                val discriminator = read(input, type.discriminator)
                val value = LinkedHashMap<String, Any?>(4)
                value[IdlType.UNION_DISCRIMINATOR] = discriminator
                type.caseFor(discriminatorKey(type.discriminator, discriminator))?.let {
                    value[it.name] = read(input, it.type)
                }
                value
            }
            is IdlType.Alias -> read(input, type.type)
        }

    private fun readElements(input: CdrInput, element: IdlType, count: Int): List<Any?> =
        when (element.resolved) {
            IdlType.Primitive.DOUBLE -> input.doubles(count).asList()
            IdlType.Primitive.OCTET -> input.octets(count).asList()
            else -> List(count) { read(input, element) }
        }

    private fun readPrimitive(input: CdrInput, type: IdlType.Primitive): Any =
        when (type) {
            IdlType.Primitive.BOOLEAN -> input.octet() != 0.toByte()
            IdlType.Primitive.CHAR -> (input.octet().toInt() and 0xff).toChar()
            IdlType.Primitive.WCHAR -> input.wideChar()
            IdlType.Primitive.OCTET -> input.octet()
            IdlType.Primitive.SHORT -> input.short()
            IdlType.Primitive.USHORT -> input.short().toInt() and 0xffff
            IdlType.Primitive.LONG -> input.long()
            IdlType.Primitive.ULONG -> input.long().toLong() and 0xffffffffL
            IdlType.Primitive.LONGLONG -> input.longLong()
            IdlType.Primitive.ULONGLONG ->
                input.longLong().let { if (it >= 0) BigInteger.valueOf(it) else BigInteger.valueOf(it).add(TWO_TO_64) }
            IdlType.Primitive.FLOAT -> input.float()
            IdlType.Primitive.DOUBLE -> input.double()
            else -> error("unknown primitive ${type.name}")
        }

    private companion object {
        val TWO_TO_64: BigInteger = BigInteger.ONE.shiftLeft(64)

        /** The fewest bytes one element can take, for checking a sequence's length before reading it. */
        fun minimumSize(type: IdlType): Int =
            when (val resolved = type.resolved) {
                is IdlType.Primitive -> resolved.size
                is IdlType.StringType,
                is IdlType.Sequence,
                is IdlType.Enum -> 4
                else -> 1
            }

        fun mismatch(expected: String, value: Any?): Nothing =
            throw Mismatch(
                "expected $expected, got ${value?.let { it::class.java.simpleName + " " + it }?.take(80) ?: "null"}"
            )

        fun number(value: Any?): Number = value as? Number ?: mismatch("a number", value)

        fun character(value: Any?): Char =
            when {
                value is Char -> value
                value is String && value.length == 1 -> value[0]
                else -> mismatch("a character", value)
            }

        fun ordinal(type: IdlType.Enum, value: Any?): Int =
            when (value) {
                is String ->
                    type.enumerators.indexOf(value).takeIf { it >= 0 }
                        ?: throw Mismatch(
                            "$value is not one of ${type.name}'s enumerators (${type.enumerators.joinToString()})"
                        )
                is Number ->
                    value.toInt().takeIf { it in type.enumerators.indices }
                        ?: throw Mismatch("${type.name} has no enumerator $value")
                else -> mismatch("an enumerator of ${type.name}", value)
            }

        /** A discriminator as union labels hold it: integers widened to Long, enumerators by name. */
        fun discriminatorKey(type: IdlType, value: Any?): Any =
            when (val resolved = type.resolved) {
                is IdlType.Enum -> if (value is Number) resolved.enumerators[value.toInt()] else value.toString()
                IdlType.Primitive.BOOLEAN,
                IdlType.Primitive.CHAR,
                IdlType.Primitive.WCHAR -> value ?: false
                else -> (value as? Number)?.toLong() ?: value ?: 0L
            }

        fun elements(value: Any?): Elements =
            when (value) {
                is DoubleArray -> Elements(value.size, { value[it] }, doubles = value)
                is ByteArray -> Elements(value.size, { value[it] }, octets = value)
                is List<*> -> Elements(value.size, value::get)
                is Array<*> -> Elements(value.size, value::get)
                is FloatArray -> Elements(value.size, value::get)
                is IntArray -> Elements(value.size, value::get)
                is LongArray -> Elements(value.size, value::get)
                is ShortArray -> Elements(value.size, value::get)
                is BooleanArray -> Elements(value.size, value::get)
                is CharArray -> Elements(value.size, value::get)
                else -> mismatch("a list or an array", value)
            }
    }

    /**
     * A value that does not fit its type, [reason] said of the member at [path] (`.geometry.size[2]`), which the
     * enclosing members prepend to as it goes up: no path is built while samples encode.
     */
    private class Mismatch(val reason: String) : RuntimeException(reason, null, false, false) {
        var path: String = ""
            private set

        fun under(segment: String): Mismatch = apply { path = segment + path }
    }

    /**
     * A sequence's or array's elements, whatever holds them; primitive arrays of the common kinds kept for bulk writes.
     */
    private class Elements(
        val size: Int,
        val get: (Int) -> Any?,
        val doubles: DoubleArray? = null,
        val octets: ByteArray? = null,
    ) {
        operator fun get(index: Int): Any? = get.invoke(index)
    }
}
