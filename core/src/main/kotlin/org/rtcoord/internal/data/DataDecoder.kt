package org.rtcoord.internal.data

import java.time.Instant
import org.rtcoord.PortData
import org.rtcoord.StructuredData
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
import org.rtcoord.datatypes.DataCodec
import org.rtcoord.datatypes.DataTypeName
import org.rtcoord.datatypes.StandardDataTypes

/**
 * Decodes the samples of one data type ([typeName] as a port declares it: `IDL:RTC/TimedDouble:1.0` in OpenRTM-aist 1.2
 * and later, `TimedDouble` before) in one byte order, with the codec the runtime encodes with. The types with a class
 * of their own become it; every other standard type becomes [StructuredData]. Bytes that do not decode as the type
 * (short, or longer than it) come out as [UnknownData], as do types it does not know.
 */
internal class DataDecoder(private val typeName: String, private val littleEndian: Boolean) {
    private val codec = typeName.takeIf { it.isNotBlank() }?.let(StandardDataTypes::named)?.let(::DataCodec)
    private val typed: ((Instant, Map<*, *>) -> PortData)? = TYPED[shortName(typeName)]

    fun decode(bytes: ByteArray): PortData {
        val codec = codec ?: return unknown(bytes)
        val value =
            try {
                codec.decode(bytes, littleEndian) as Map<*, *>
            } catch (e: IllegalArgumentException) {
                return unknown(bytes)
            }
        val time = time(value["tm"])
        return if (typed != null && time != null) typed.invoke(time, value) else StructuredData(typeName, time, value)
    }

    private fun unknown(bytes: ByteArray) = UnknownData(typeName, bytes, littleEndian)

    companion object {
        /** `TimedDouble` from `IDL:RTC/TimedDouble:1.0`, `RTC::TimedDouble` or `TimedDouble`. */
        fun shortName(typeName: String): String = if (typeName.isBlank()) "" else DataTypeName.simpleName(typeName)

        /** `RTC::Time` as an instant; null when [tm] is no time stamp. */
        private fun time(tm: Any?): Instant? {
            val fields = tm as? Map<*, *> ?: return null
            val seconds = fields["sec"] as? Long ?: return null
            val nanos = fields["nsec"] as? Long ?: return null
            return Instant.ofEpochSecond(seconds, nanos.coerceAtMost(999_999_999))
        }

        private fun Map<*, *>.member(name: String): Map<*, *> = get(name) as Map<*, *>

        @Suppress("UNCHECKED_CAST")
        private val TYPED: Map<String, (Instant, Map<*, *>) -> PortData> =
            mapOf(
                "TimedBoolean" to { t, v -> TimedBoolean(t, v["data"] as Boolean) },
                "TimedOctet" to { t, v -> TimedOctet(t, v["data"] as Byte) },
                "TimedShort" to { t, v -> TimedShort(t, v["data"] as Short) },
                "TimedLong" to { t, v -> TimedLong(t, v["data"] as Int) },
                "TimedFloat" to { t, v -> TimedFloat(t, v["data"] as Float) },
                "TimedDouble" to { t, v -> TimedDouble(t, v["data"] as Double) },
                "TimedString" to { t, v -> TimedString(t, v["data"] as String) },
                "TimedLongSeq" to { t, v -> TimedLongSeq(t, v["data"] as List<Int>) },
                "TimedFloatSeq" to { t, v -> TimedFloatSeq(t, v["data"] as List<Float>) },
                "TimedDoubleSeq" to { t, v -> TimedDoubleSeq(t, v["data"] as List<Double>) },
                "TimedPoint2D" to
                    { t, v ->
                        v.member("data").let { TimedPoint2D(t, it["x"] as Double, it["y"] as Double) }
                    },
                "TimedPose2D" to
                    { t, v ->
                        val pose = v.member("data")
                        val position = pose.member("position")
                        TimedPose2D(t, position["x"] as Double, position["y"] as Double, pose["heading"] as Double)
                    },
                "TimedVelocity2D" to
                    { t, v ->
                        v.member("data").let {
                            TimedVelocity2D(t, it["vx"] as Double, it["vy"] as Double, it["va"] as Double)
                        }
                    },
            )
    }
}
