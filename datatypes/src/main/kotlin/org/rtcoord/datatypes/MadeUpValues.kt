package org.rtcoord.datatypes

import java.util.Collections
import java.util.concurrent.ConcurrentHashMap
import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.sin

/**
 * Made-up samples of one data type for a simulated out-port: deterministic from the time stamp and the port's [seed] (a
 * test can compute what a port sends at a given time), different at every sample, and plausible where the type says
 * what plausible is: a `tm` member is the time stamp itself, a `RangeData` is a 1081-beam scan whose ranges lie within
 * its configuration's limits (the scanner's geometry and configuration stay as they are, as a mounted scanner's do), a
 * `CameraImage` holds `width * height * bpp / 8` pixel bytes. Numbers move smoothly (sines of the time); enumerators,
 * union cases and booleans change every second or so.
 */
public class MadeUpValues(public val type: IdlType, private val seed: Int) {
    /** The sample stamped [timeNanos] (nanoseconds since the epoch), as [DataCodec] encodes it. */
    public fun at(timeNanos: Long): Any? = value(type, timeNanos, seed)

    /** Each scanner's members that stay as they are from one scan to the next, by the scanner's key: made once. */
    private val scanners = ConcurrentHashMap<Int, Map<String, Any?>>()

    private fun value(type: IdlType, time: Long, key: Int): Any? {
        if (type is IdlType.Struct)
            SPECIAL[type.repositoryId]?.let {
                return it(this, type, time, key)
            }
        return when (type) {
            is IdlType.Alias -> value(type.type, time, key)
            is IdlType.Primitive -> primitive(type, time, key)
            is IdlType.StringType ->
                "${if (type.wide) "wide " else ""}sample ${time / 1_000_000}"
                    .take(if (type.bound > 0) type.bound else Int.MAX_VALUE)
            is IdlType.Sequence ->
                elements(
                    type.element,
                    if (type.bound > 0) minOf(SEQUENCE_LENGTH, type.bound) else SEQUENCE_LENGTH,
                    time,
                    key,
                )
            is IdlType.ArrayType -> elements(type.element, type.length, time, key)
            is IdlType.Struct -> members(type, time, key)
            is IdlType.Enum -> type.enumerators[step(time, key, SLOW_MILLIS, type.enumerators.size)]
            is IdlType.Union -> union(type, time, key)
        }
    }

    /** A struct's members, each made up on its own. */
    private fun members(type: IdlType.Struct, time: Long, key: Int): MutableMap<String, Any?> =
        LinkedHashMap<String, Any?>().apply {
            for (member in type.members) {
                put(
                    member.name,
                    if (member.name == "tm" && member.type.isTime()) time(time)
                    else value(member.type, time, mix(key, member.name)),
                )
            }
        }

    private fun elements(element: IdlType, count: Int, time: Long, key: Int): Any =
        when (element.resolved) {
            IdlType.Primitive.DOUBLE -> DoubleArray(count) { wave(time, mix(key, it)) }
            IdlType.Primitive.OCTET -> ByteArray(count) { (step(time, mix(key, it), FAST_MILLIS, 256)).toByte() }
            else -> List(count) { value(element, time, mix(key, it)) }
        }

    private fun union(type: IdlType.Union, time: Long, key: Int): Map<String, Any?> {
        val labelled = type.cases.filter { !it.isDefault }
        if (labelled.isEmpty()) return mapOf(IdlType.UNION_DISCRIMINATOR to discriminatorFor(type, null))
        val case = labelled[step(time, key, SLOW_MILLIS, labelled.size)]
        return linkedMapOf(
            IdlType.UNION_DISCRIMINATOR to discriminatorFor(type, case.labels.first()),
            case.name to value(case.type, time, mix(key, case.name)),
        )
    }

    /** A label as the discriminator's own type writes it. */
    private fun discriminatorFor(type: IdlType.Union, label: Any?): Any =
        when (val discriminator = type.discriminator.resolved) {
            is IdlType.Enum -> label ?: discriminator.enumerators.first()
            IdlType.Primitive.BOOLEAN -> label ?: false
            IdlType.Primitive.CHAR,
            IdlType.Primitive.WCHAR -> label ?: 'a'
            else -> (label as? Long) ?: 0L
        }

    private fun primitive(type: IdlType.Primitive, time: Long, key: Int): Any =
        when (type) {
            IdlType.Primitive.BOOLEAN -> step(time, key, SLOW_MILLIS, 2) == 1
            IdlType.Primitive.CHAR,
            IdlType.Primitive.WCHAR -> 'a' + step(time, key, FAST_MILLIS, 26)
            IdlType.Primitive.OCTET -> step(time, key, FAST_MILLIS, 256).toByte()
            IdlType.Primitive.SHORT,
            IdlType.Primitive.USHORT -> step(time, key, FAST_MILLIS, 1000).toShort()
            IdlType.Primitive.LONG,
            IdlType.Primitive.ULONG -> step(time, key, FAST_MILLIS, 1_000_000)
            IdlType.Primitive.LONGLONG,
            IdlType.Primitive.ULONGLONG -> step(time, key, FAST_MILLIS, 1_000_000).toLong()
            IdlType.Primitive.FLOAT -> wave(time, key).toFloat()
            IdlType.Primitive.DOUBLE -> wave(time, key)
            else -> error("unknown primitive ${type.name}")
        }

    private fun time(nanos: Long): Map<String, Any?> =
        linkedMapOf("sec" to nanos / 1_000_000_000, "nsec" to nanos % 1_000_000_000)

    private fun IdlType.isTime(): Boolean = (resolved as? IdlType.Struct)?.repositoryId == TIME

    private companion object {
        const val TIME = "IDL:RTC/Time:1.0"
        const val SEQUENCE_LENGTH = 4
        const val FAST_MILLIS = 10L
        const val SLOW_MILLIS = 1000L
        const val BEAMS = 1081

        /** Values of the device types whose members depend on each other. */
        val SPECIAL: Map<String, MadeUpValues.(IdlType.Struct, Long, Int) -> Any?> =
            mapOf(
                "IDL:RTC/RangeData:1.0" to { type, time, key -> ranger(type, time, key, "ranges") },
                "IDL:RTC/IntensityData:1.0" to { type, time, key -> ranger(type, time, key, "intensities") },
                "IDL:RTC/CameraImage:1.0" to { type, time, key -> cameraImage(type, time, key) },
                "IDL:RTC/PointCloud:1.0" to { type, time, key -> pointCloud(type, time, key) },
            )

        /**
         * A 270-degree scanner with a quarter-degree resolution, as common laser rangers are: 1081 beams. Only the time
         * and the [readings] change from scan to scan; the scanner's geometry and configuration are made once (a scan
         * at 100 Hz would otherwise make them up again, map by map and sine by sine, every 10 ms) and shared by every
         * scan, read-only.
         */
        fun MadeUpValues.ranger(type: IdlType.Struct, time: Long, key: Int, readings: String): Any? {
            val fixed = scanners.getOrPut(key) { scanner(type, key, readings) }
            return LinkedHashMap<String, Any?>(type.members.size * 2).apply {
                for (member in type.members) {
                    put(
                        member.name,
                        when (member.name) {
                            "tm" -> time(time)
                            readings -> sineRanges(BEAMS, phase = time / 1e9 + key)
                            else -> fixed[member.name]
                        },
                    )
                }
            }
        }

        /** A scanner's members other than the time and the readings, as its scans share them. */
        fun MadeUpValues.scanner(type: IdlType.Struct, key: Int, readings: String): Map<String, Any?> =
            type.members
                .filter { it.name != "tm" && it.name != readings }
                .associateTo(LinkedHashMap()) { member ->
                    member.name to
                        readOnly(
                            if (member.name == "config")
                                mapOf(
                                    "minAngle" to -0.75 * PI,
                                    "maxAngle" to 0.75 * PI,
                                    "angularRes" to 1.5 * PI / (BEAMS - 1),
                                    "minRange" to 0.02,
                                    "maxRange" to 30.0,
                                    "rangeRes" to 0.001,
                                    "frequency" to 40.0,
                                )
                            else value(member.type, 0, mix(key, member.name))
                        )
                }

        /** [value] with every map and list in it made read-only, to be shared by samples. */
        fun readOnly(value: Any?): Any? =
            when (value) {
                is Map<*, *> -> Collections.unmodifiableMap(value.mapValuesTo(LinkedHashMap()) { readOnly(it.value) })
                is List<*> -> Collections.unmodifiableList(value.map(::readOnly))
                else -> value
            }

        fun MadeUpValues.cameraImage(type: IdlType.Struct, time: Long, key: Int): Any? {
            val generic = members(type, time, key)
            val width = 160
            val height = 120
            val shift = step(time, key, FAST_MILLIS, 256)
            generic.putAll(mapOf("width" to width, "height" to height, "bpp" to 24, "format" to "", "fDiv" to 1.0))
            generic["pixels"] = ByteArray(width * height * 3) { ((it / 3 + shift) and 0xff).toByte() }
            return generic
        }

        fun MadeUpValues.pointCloud(type: IdlType.Struct, time: Long, key: Int): Any? {
            val generic = members(type, time, key)
            val point = (type.members.first { it.name == "points" }.type.resolved as IdlType.Sequence).element
            generic["points"] = List(100) { value(point, time, mix(key, it)) }
            return generic
        }

        /**
         * 2 to 5 m along the beams, a sine of the beam's angle shifted by [phase]: walls coming and going. The sines
         * come by rotation (two multiplications each) rather than a `sin` per beam: a scan costs microseconds, so a
         * simulated ranger at 100 Hz stays well under 1 % of a core.
         */
        fun sineRanges(beams: Int, phase: Double): DoubleArray {
            val step = 0.02
            val stepSin = sin(step)
            val stepCos = kotlin.math.cos(step)
            var s = sin(phase)
            var c = kotlin.math.cos(phase)
            return DoubleArray(beams) {
                val range = 3.5 + 1.5 * s
                val next = s * stepCos + c * stepSin
                c = c * stepCos - s * stepSin
                s = next
                range
            }
        }

        /** A smooth value in [-1, 1] around a base of its own: a sine of the time, its phase and period from [key]. */
        fun wave(time: Long, key: Int): Double = (abs(key) % 100) / 10.0 + sin(time / 1e9 * (1 + abs(key) % 7) + key)

        /** A whole number in `0 until bound` that advances every [millis] milliseconds. */
        fun step(time: Long, key: Int, millis: Long, bound: Int): Int =
            (((time / 1_000_000 / millis) + abs(key)) % bound).toInt()

        fun mix(key: Int, part: Any): Int = 31 * key + part.hashCode()
    }
}
