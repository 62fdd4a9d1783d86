package org.rtcoord.internal.logs

import java.io.ByteArrayInputStream
import java.io.IOException
import java.io.InputStream
import java.time.Instant
import java.util.zip.GZIPInputStream
import org.msgpack.core.MessagePack
import org.msgpack.core.MessagePackException
import org.msgpack.value.ValueType

/**
 * Reads the frames of the Fluentd forward protocol (v1) into events, in its four modes, told apart by the frame's
 * second element:
 *
 * |mode                   |frame                                                                                |second element                   |
 * |-----------------------|-------------------------------------------------------------------------------------|---------------------------------|
 * |Message                |`[tag, time, record, option?]`                                                       |a time: integer, float, extension|
 * |Forward                |`[tag, [[time, record], ...], option?]`                                              |an array                         |
 * |PackedForward          |`[tag, entries, option?]`, the entries `[time, record]` MessagePack one after another|str or bin                       |
 * |CompressedPackedForward|the same, gzipped (one or more gzip members), with the option `compressed: "gzip"`   |str or bin                       |
 *
 * A nil frame is a heartbeat and carries nothing. The option's `chunk` asks for an acknowledgement, which the
 * connection sends once the frame's events are handed on.
 *
 * @property maxRecordBytes what one packed entry may take, uncompressed.
 * @property now the time given to an event sent without one (nil or 0), as in_forward gives it.
 */
internal class ForwardFrames(private val maxRecordBytes: Int, private val now: () -> Instant = Instant::now) {
    /**
     * Reads one frame from [values] and hands its events to [event] in the order they came. Returns the option's
     * `chunk`, to acknowledge, or null.
     */
    fun read(values: BoundedValues, event: (tag: String, time: Instant, record: Map<String, Any?>) -> Unit): String? {
        when (val type = values.nextType()) {
            ValueType.NIL -> {
                values.nil()
                return null
            }
            ValueType.ARRAY -> Unit
            else -> throw values.malformed("a frame is an array, not ${type.name.lowercase()}")
        }
        val size = values.arrayHeader("a frame")
        if (size !in 2..4) throw values.malformed("a frame is an array of 2 to 4 elements, not $size")
        val tag = values.text("the tag")
        val option: Map<String, Any?>?
        when (values.nextType()) {
            ValueType.ARRAY -> {
                if (size > 3) throw values.malformed("a Forward frame has 2 or 3 elements, not $size")
                repeat(values.arrayHeader("the entries")) {
                    val (time, record) = entry(values)
                    values.checkUsed()
                    event(tag, time, record)
                }
                option = if (size == 3) values.map("the option") else null
            }
            ValueType.STRING,
            ValueType.BINARY -> {
                if (size > 3) throw values.malformed("a PackedForward frame has 2 or 3 elements, not $size")
                val packed = values.raw("the packed entries")
                option = if (size == 3) values.map("the option") else null
                val gzipped =
                    when (val compressed = option?.get("compressed")) {
                        null,
                        "text" -> false
                        "gzip" -> true
                        else -> throw values.malformed("the option's compressed is '$compressed', not gzip or text")
                    }
                unpack(tag, packed, gzipped, values, event)
            }
            else -> {
                if (size < 3) throw values.malformed("a Message frame has 3 or 4 elements, not $size")
                val time = values.time() ?: now()
                val record = values.map("the record")
                option = if (size == 4) values.map("the option") else null
                event(tag, time, record)
            }
        }
        return when (val chunk = option?.get("chunk")) {
            null -> null
            is String -> chunk
            is ByteArray -> String(chunk, Charsets.UTF_8)
            else -> throw values.malformed("the option's chunk is not a string")
        }
    }

    /** Reads the entries of a PackedForward frame one at a time: each entry, not the whole, is bounded. */
    private fun unpack(
        tag: String,
        packed: ByteArray,
        gzipped: Boolean,
        frame: BoundedValues,
        event: (String, Instant, Map<String, Any?>) -> Unit,
    ) {
        val input: InputStream = ByteArrayInputStream(packed)
        try {
            // GZIPInputStream reads every member of a concatenation, as senders that append chunks write them.
            MessagePack.newDefaultUnpacker(if (gzipped) GZIPInputStream(input) else input).use { unpacker ->
                val values = BoundedValues(unpacker, maxRecordBytes, "a packed entry")
                while (unpacker.hasNext()) {
                    values.begin()
                    val (time, record) = entry(values)
                    values.checkUsed()
                    event(tag, time, record)
                }
            }
        } catch (e: MessagePackException) {
            throw frame.malformed("the packed entries do not decode: ${e.message ?: e.javaClass.simpleName}")
        } catch (e: IOException) {
            throw frame.malformed("the packed entries do not decompress: ${e.message ?: e.javaClass.simpleName}")
        }
    }

    /** Reads one `[time, record]` entry. */
    private fun entry(values: BoundedValues): Pair<Instant, Map<String, Any?>> {
        val size = values.arrayHeader("an entry")
        if (size != 2) throw values.malformed("an entry is [time, record], not an array of $size")
        val time = values.time() ?: now()
        return time to values.map("the record")
    }
}
