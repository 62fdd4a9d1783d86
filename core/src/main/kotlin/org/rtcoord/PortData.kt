package org.rtcoord

import java.time.Instant

/**
 * One sample of a data port, decoded from the CDR bytes the port pushed, in the byte order its
 * connector negotiated. The standard types of OpenRTM-aist's BasicDataType and ExtendedDataTypes
 * become the classes below, each with the time stamp the writer put in it (`tm`); any other type
 * arrives as [UnknownData]: its type name and the raw bytes.
 */
public sealed class PortData {
    /** The writer's time stamp (`tm`), null when the type is unknown. */
    public abstract val time: Instant?
}

/** `RTC::TimedBoolean`. */
public data class TimedBoolean(override val time: Instant, val data: Boolean) : PortData()

/** `RTC::TimedOctet`. */
public data class TimedOctet(override val time: Instant, val data: Byte) : PortData()

/** `RTC::TimedShort`. */
public data class TimedShort(override val time: Instant, val data: Short) : PortData()

/** `RTC::TimedLong` (a 32-bit IDL long). */
public data class TimedLong(override val time: Instant, val data: Int) : PortData()

/** `RTC::TimedFloat`. */
public data class TimedFloat(override val time: Instant, val data: Float) : PortData()

/** `RTC::TimedDouble`. */
public data class TimedDouble(override val time: Instant, val data: Double) : PortData()

/** `RTC::TimedString`. */
public data class TimedString(override val time: Instant, val data: String) : PortData()

/** `RTC::TimedLongSeq`. */
public data class TimedLongSeq(override val time: Instant, val data: List<Int>) : PortData()

/** `RTC::TimedFloatSeq`. */
public data class TimedFloatSeq(override val time: Instant, val data: List<Float>) : PortData()

/** `RTC::TimedDoubleSeq` (a laser scan's ranges, for instance). */
public data class TimedDoubleSeq(override val time: Instant, val data: List<Double>) : PortData()

/** `RTC::TimedPoint2D` of ExtendedDataTypes. */
public data class TimedPoint2D(override val time: Instant, val x: Double, val y: Double) : PortData()

/** `RTC::TimedPose2D` of ExtendedDataTypes: a position and a [heading] in radians. */
public data class TimedPose2D(override val time: Instant, val x: Double, val y: Double, val heading: Double) : PortData()

/** `RTC::TimedVelocity2D` of ExtendedDataTypes: velocities along x and y and the angular velocity [va]. */
public data class TimedVelocity2D(override val time: Instant, val vx: Double, val vy: Double, val va: Double) : PortData()

/**
 * A sample of a type not decoded here, or one whose bytes did not decode as its type: [typeName] as the
 * port declares it and the [bytes] as they came, in the byte order [littleEndian] says.
 */
public class UnknownData(public val typeName: String, bytes: ByteArray, public val littleEndian: Boolean) : PortData() {
    private val raw = bytes.copyOf()

    override val time: Instant? get() = null

    /** A copy of the raw CDR bytes. */
    public val bytes: ByteArray get() = raw.copyOf()

    override fun equals(other: Any?): Boolean =
        other is UnknownData && other.typeName == typeName && other.littleEndian == littleEndian && other.raw.contentEquals(raw)

    override fun hashCode(): Int = typeName.hashCode() * 31 + raw.contentHashCode()

    override fun toString(): String = "UnknownData($typeName, ${raw.size} bytes)"
}

/** Receives a port's samples (see [Port.tap]). */
public fun interface DataListener {
    /**
     * Called with each sample, in the order the port sent them, on the thread that received it: return
     * quickly (hand the sample on), since the port's next sample waits for the call to return.
     */
    public fun onData(data: PortData)
}
