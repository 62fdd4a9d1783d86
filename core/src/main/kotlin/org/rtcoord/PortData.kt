package org.rtcoord

import java.time.Instant
import org.rtcoord.internal.ValueFields

/**
 * One sample of a data port, decoded from the CDR bytes the port pushed, in the byte order its connector negotiated.
 * The commonest standard types of OpenRTM-aist's BasicDataType and ExtendedDataTypes become the classes below, each
 * with the time stamp the writer put in it (`tm`); every other type of those files and of InterfaceDataTypes
 * (RangeData, CameraImage, PointCloud, ...) becomes [StructuredData]; any other type arrives as [UnknownData]: its type
 * name and the raw bytes.
 */
public sealed class PortData : ValueObject() {
    /** The writer's time stamp (`tm`), null when the type is unknown. */
    public abstract val time: Instant?
}

/** `RTC::TimedBoolean`. */
public class TimedBoolean(override val time: Instant, public val data: Boolean) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedOctet`. */
public class TimedOctet(override val time: Instant, public val data: Byte) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedShort`. */
public class TimedShort(override val time: Instant, public val data: Short) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedLong` (a 32-bit IDL long). */
public class TimedLong(override val time: Instant, public val data: Int) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedFloat`. */
public class TimedFloat(override val time: Instant, public val data: Float) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedDouble`. */
public class TimedDouble(override val time: Instant, public val data: Double) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedString`. */
public class TimedString(override val time: Instant, public val data: String) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedLongSeq`. */
public class TimedLongSeq(override val time: Instant, public val data: List<Int>) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedFloatSeq`. */
public class TimedFloatSeq(override val time: Instant, public val data: List<Float>) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedDoubleSeq` (a laser scan's ranges, for instance). */
public class TimedDoubleSeq(override val time: Instant, public val data: List<Double>) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "data" to data)
}

/** `RTC::TimedPoint2D` of ExtendedDataTypes. */
public class TimedPoint2D(override val time: Instant, public val x: Double, public val y: Double) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "x" to x, "y" to y)
}

/** `RTC::TimedPose2D` of ExtendedDataTypes: a position and a [heading] in radians. */
public class TimedPose2D(
    override val time: Instant,
    public val x: Double,
    public val y: Double,
    public val heading: Double,
) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "x" to x, "y" to y, "heading" to heading)
}

/** `RTC::TimedVelocity2D` of ExtendedDataTypes: velocities along x and y and the angular velocity [va]. */
public class TimedVelocity2D(
    override val time: Instant,
    public val vx: Double,
    public val vy: Double,
    public val va: Double,
) : PortData() {
    override fun fields(): ValueFields = ValueFields("time" to time, "vx" to vx, "vy" to vy, "va" to va)
}

/**
 * A sample of a standard type without a class of its own above (`RTC::RangeData`, `RTC::CameraImage`,
 * `RTC::TimedPose3D`, ...): [typeName] as the port declares it, the time stamp of its `tm` member (null when it has
 * none) and its [members], member by member as the IDL declares them. A struct is a [Map] of member name to value in
 * declaration order; a sequence or an array is a [List]; an enum is its enumerator's name; `boolean`, `octet`, `char`,
 * `short`, `long`, `long long`, `float`, `double` and `string` are [Boolean], [Byte], [Char], [Short], [Int], [Long],
 * [Float], [Double] and [String]; `unsigned short` is an [Int], `unsigned long` a [Long], `unsigned long long` a
 * [java.math.BigInteger].
 */
public class StructuredData(public val typeName: String, override val time: Instant?, fields: Map<*, *>) : PortData() {
    /** The sample's members by name, in declaration order (its `tm` included). */
    public val members: Map<String, Any?> =
        java.util.Collections.unmodifiableMap(
            fields.entries.associateTo(LinkedHashMap()) { it.key.toString() to it.value }
        )

    /** The member [name] (a path through nested structs: `config.maxRange`), or null when there is none. */
    public fun member(name: String): Any? =
        name.split('.').fold(members as Any?) { value, part -> (value as? Map<*, *>)?.get(part) }

    override fun fields(): ValueFields = ValueFields("typeName" to typeName, "time" to time, "members" to members)
}

/**
 * A sample of a type not decoded here, or one whose bytes did not decode as its type: [typeName] as the port declares
 * it and the [bytes] as they came, in the byte order [littleEndian] says.
 */
public class UnknownData(public val typeName: String, bytes: ByteArray, public val littleEndian: Boolean) : PortData() {
    private val raw = Bytes(bytes.copyOf())

    override val time: Instant?
        get() = null

    /** A copy of the raw CDR bytes. */
    public val bytes: ByteArray
        get() = raw.content.copyOf()

    override fun fields(): ValueFields =
        ValueFields("typeName" to typeName, "bytes" to raw, "littleEndian" to littleEndian)

    /** Bytes compared by content and shown by their count: a sample can be large. */
    private class Bytes(val content: ByteArray) {
        override fun equals(other: Any?): Boolean = other is Bytes && other.content.contentEquals(content)

        override fun hashCode(): Int = content.contentHashCode()

        override fun toString(): String = "${content.size} bytes"
    }
}

/** Receives a port's samples (see [Port.tap]). */
public fun interface DataListener {
    /**
     * Called with each sample, in the order the port sent them, on the thread that received it: return quickly (hand
     * the sample on), since the port's next sample waits for the call to return.
     */
    public fun onData(data: PortData)
}
