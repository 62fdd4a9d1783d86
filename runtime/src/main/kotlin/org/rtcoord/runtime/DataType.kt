package org.rtcoord.runtime

import org.rtcoord.datatypes.DataCodec
import org.rtcoord.datatypes.DataTypeName
import org.rtcoord.datatypes.IdlType
import org.rtcoord.datatypes.StandardDataTypes
import org.rtcoord.datatypes.resolved

/**
 * The data type a port carries: the [repositoryId] its `dataport.data_type` advertises and, when its IDL is known
 * ([idl]), how its samples are encoded, by the one codec core decodes them with. A port of a type whose IDL is not
 * known still connects as the real one does, but its out-port sends nothing.
 */
public class DataType(repositoryId: String, public val idl: IdlType?) {
    /** `IDL:RTC/TimedLong:1.0` and so on, whatever form it was given in. */
    public val repositoryId: String = DataTypeName.repositoryId(repositoryId)

    private val codec = idl?.let(::DataCodec)

    /** The `data` member of a `Timed...` type: the value alone stands for the sample, time-stamped on writing. */
    private val dataMember =
        (idl?.resolved as? IdlType.Struct)
            ?.members
            ?.takeIf { members -> members.size == 2 && members[0].name == "tm" && members[1].name == "data" }
            ?.get(1)
            ?.type

    /** Whether samples of this type can be encoded (its IDL is known). */
    public val isEncodable: Boolean
        get() = codec != null

    /**
     * Encodes [value] in the byte order a connector negotiated: a whole sample (a [Map] as
     * [org.rtcoord.datatypes.DataCodec] takes it), or for a `Timed...` type with one `data` member the data alone (an
     * Int, a Double, a DoubleArray, a String, ...) stamped with [timeNanos]. Throws [IllegalStateException] when the
     * type's IDL is not known and [IllegalArgumentException] when the value does not fit it.
     */
    public fun encode(value: Any, timeNanos: Long, littleEndian: Boolean = true): ByteArray {
        val codec = checkNotNull(codec) { "$repositoryId: its IDL is not known, so its samples cannot be encoded" }
        val sample =
            if (value is Map<*, *> || dataMember == null) value else mapOf("tm" to time(timeNanos), "data" to value)
        return codec.encode(sample, littleEndian)
    }

    /**
     * Decodes a sample in the given byte order: its time stamp and, for a `Timed...` type with one `data` member, that
     * member (a sequence of doubles as a DoubleArray), else the whole sample. Throws [IllegalArgumentException] on
     * malformed data and [IllegalStateException] when the IDL is not known.
     */
    public fun decode(data: ByteArray, littleEndian: Boolean = true): Sample {
        val codec = checkNotNull(codec) { "$repositoryId: its IDL is not known, so its samples cannot be decoded" }
        val decoded = checkNotNull(codec.decode(data, littleEndian))
        val sample = decoded as? Map<*, *> ?: return Sample(0, decoded)
        val tm = sample["tm"] as? Map<*, *>
        val time = tm?.let { (it["sec"] as Long) * 1_000_000_000 + it["nsec"] as Long } ?: 0
        val value: Any =
            if (dataMember == null) sample
            else
                when (val data = sample["data"]) {
                    is List<*> ->
                        if ((dataMember.resolved as? IdlType.Sequence)?.element?.resolved === IdlType.Primitive.DOUBLE)
                            DoubleArray(data.size) { data[it] as Double }
                        else data
                    else -> data!!
                }
        return Sample(time, value)
    }

    override fun equals(other: Any?): Boolean = other is DataType && other.repositoryId == repositoryId

    override fun hashCode(): Int = repositoryId.hashCode()

    override fun toString(): String = repositoryId

    public companion object {
        @JvmField public val TIMED_LONG: DataType = standard("TimedLong")
        @JvmField public val TIMED_DOUBLE: DataType = standard("TimedDouble")
        @JvmField public val TIMED_DOUBLE_SEQ: DataType = standard("TimedDoubleSeq")
        @JvmField public val TIMED_STRING: DataType = standard("TimedString")

        /** The standard type [name] means (`IDL:RTC/TimedPose2D:1.0`, `TimedPose2D`, ...), or null. */
        @JvmStatic public fun of(name: String): DataType? = StandardDataTypes.named(name)?.let { DataType(name, it) }

        private fun standard(name: String): DataType = checkNotNull(of(name)) { "$name is missing from the idl module" }

        private fun time(nanos: Long): Map<String, Any> =
            mapOf("sec" to nanos / 1_000_000_000, "nsec" to nanos % 1_000_000_000)
    }
}

/** One value read from a port and the time stamp it was written with. */
public data class Sample(val timeNanos: Long, val value: Any)
