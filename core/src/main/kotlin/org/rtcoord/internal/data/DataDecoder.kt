package org.rtcoord.internal.data

import org.rtcoord.PortData
import org.rtcoord.TimedBoolean
import org.rtcoord.TimedDouble
import org.rtcoord.TimedDoubleSeq
import org.rtcoord.TimedFloat
import org.rtcoord.TimedFloatSeq
import org.rtcoord.TimedLong
import org.rtcoord.TimedLongSeq
import org.rtcoord.TimedOctet
import org.rtcoord.TimedPoint2D
import org.rtcoord.TimedPose2D
import org.rtcoord.TimedShort
import org.rtcoord.TimedString
import org.rtcoord.TimedVelocity2D
import org.rtcoord.UnknownData
import java.nio.ByteOrder
import java.time.Instant

/**
 * Decodes the samples of one data type ([typeName] as a port declares it: `IDL:RTC/TimedDouble:1.0`
 * in OpenRTM-aist 1.2 and later, `TimedDouble` before) in one byte order. Bytes that do not decode as
 * the type (short, or longer than it) come out as [UnknownData], as do types it does not know.
 */
internal class DataDecoder(private val typeName: String, littleEndian: Boolean) {
    private val order = if (littleEndian) ByteOrder.LITTLE_ENDIAN else ByteOrder.BIG_ENDIAN
    private val read: ((CdrReader) -> PortData)? = READERS[shortName(typeName)]

    fun decode(bytes: ByteArray): PortData {
        val reader = read ?: return unknown(bytes)
        return try {
            val cdr = CdrReader(bytes, order)
            reader(cdr).takeIf { cdr.exhausted } ?: unknown(bytes)
        } catch (e: IllegalArgumentException) {
            unknown(bytes)
        }
    }

    private fun unknown(bytes: ByteArray) = UnknownData(typeName, bytes, order == ByteOrder.LITTLE_ENDIAN)

    companion object {
        /** `TimedDouble` from `IDL:RTC/TimedDouble:1.0`, `RTC::TimedDouble` or `TimedDouble`. */
        fun shortName(typeName: String): String {
            val name = typeName.trim()
            return if (name.startsWith("IDL:")) name.removePrefix("IDL:").substringBeforeLast(':').substringAfterLast('/') else name.substringAfterLast("::")
        }

        private fun CdrReader.time(): Instant {
            val seconds = ulong()
            val nanos = ulong()
            return Instant.ofEpochSecond(seconds, nanos.coerceAtMost(999_999_999))
        }

        private val READERS: Map<String, (CdrReader) -> PortData> = mapOf(
            "TimedBoolean" to { r -> TimedBoolean(r.time(), r.boolean()) },
            "TimedOctet" to { r -> TimedOctet(r.time(), r.octet()) },
            "TimedShort" to { r -> TimedShort(r.time(), r.short()) },
            "TimedLong" to { r -> TimedLong(r.time(), r.long()) },
            "TimedFloat" to { r -> TimedFloat(r.time(), r.float()) },
            "TimedDouble" to { r -> TimedDouble(r.time(), r.double()) },
            "TimedString" to { r -> TimedString(r.time(), r.string()) },
            "TimedLongSeq" to { r -> TimedLongSeq(r.time(), List(r.length(4)) { r.long() }) },
            "TimedFloatSeq" to { r -> TimedFloatSeq(r.time(), List(r.length(4)) { r.float() }) },
            "TimedDoubleSeq" to { r -> TimedDoubleSeq(r.time(), List(r.length(8)) { r.double() }) },
            "TimedPoint2D" to { r -> TimedPoint2D(r.time(), r.double(), r.double()) },
            "TimedPose2D" to { r -> TimedPose2D(r.time(), r.double(), r.double(), r.double()) },
            "TimedVelocity2D" to { r -> TimedVelocity2D(r.time(), r.double(), r.double(), r.double()) },
        )
    }
}
