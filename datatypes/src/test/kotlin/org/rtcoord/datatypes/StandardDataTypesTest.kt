package org.rtcoord.datatypes

import java.nio.file.Paths
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNotEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * Every struct of OpenRTM-aist's three data type files: known by its name, the same whether read from idlj's TypeCodes
 * (what rtcoord runs on) or parsed from the IDL at run time, and through the codec and back in both byte orders.
 */
class StandardDataTypesTest {
    private val idl =
        Paths.get(System.getProperty("rtcoord.root") ?: "..").resolve("idl/src/main/idl").toAbsolutePath().normalize()
    private val parsed = IdlFiles.read(listOf(idl.resolve("InterfaceDataTypes.idl")))
    private val structs = parsed.types.values.filterIsInstance<IdlType.Struct>()

    @Test
    fun `every struct of the three files is a standard type, as its IDL declares it`() {
        assertEquals(126, structs.size, "the structs of BasicDataType, ExtendedDataTypes and InterfaceDataTypes")
        for (struct in structs) {
            val standard = StandardDataTypes.named(struct.repositoryId)
            assertEquals(struct.describe(), standard?.describe(), struct.name)
        }
    }

    @Test
    fun `every struct survives the codec in both byte orders`() {
        for (struct in structs) {
            val codec = DataCodec(StandardDataTypes.named(struct.repositoryId)!!)
            val value = MadeUpValues(codec.type, seed = 7).at(1_700_000_000_123_456_789)
            for (littleEndian in listOf(true, false)) {
                val bytes = codec.encode(value, littleEndian)
                assertEquals(
                    comparable(value),
                    comparable(codec.decode(bytes, littleEndian)),
                    "${struct.name}, little-endian $littleEndian",
                )
            }
        }
    }

    @Test
    fun `the byte orders differ where a value has more than one byte`() {
        val pose = DataCodec(StandardDataTypes.named("TimedPose2D")!!)
        val value = MadeUpValues(pose.type, seed = 1).at(1_000_000_001)
        val little = pose.encode(value, littleEndian = true)
        val big = pose.encode(value, littleEndian = false)
        assertEquals(8 + 3 * 8, little.size, "Time then three doubles, the first aligned to 8")
        assertEquals(listOf<Byte>(1, 0, 0, 0), little.take(4))
        assertEquals(listOf<Byte>(0, 0, 0, 1), big.take(4))
        assertNotEquals(little.toList(), big.toList())
    }

    @Test
    fun `a value that does not fit is refused, naming the member at fault`() {
        val codec = DataCodec(StandardDataTypes.named("RangeData")!!)
        @Suppress("UNCHECKED_CAST")
        val value = MadeUpValues(codec.type, seed = 3).at(1_000_000_001) as MutableMap<String, Any?>
        fun Map<*, *>.with(name: String, change: MutableMap<Any?, Any?>.() -> Unit) =
            toMutableMap().apply { this[name] = (this[name] as Map<*, *>).toMutableMap().apply(change) }
        value["geometry"] =
            (value["geometry"] as Map<*, *>).with("geometry") {
                this["size"] = (this["size"] as Map<*, *>).toMutableMap().apply { this["l"] = "long" }
            }
        val wrong = assertThrows(IllegalArgumentException::class.java) { codec.encode(value, littleEndian = true) }
        assertEquals("RTC::RangeData.geometry.geometry.size.l: expected a number, got String long", wrong.message)
        value.remove("ranges")
        val missing = assertThrows(IllegalArgumentException::class.java) { codec.encode(value, littleEndian = true) }
        assertEquals("RTC::RangeData.ranges: missing", missing.message)
        val points = DataCodec(StandardDataTypes.named("PointCloud")!!)
        @Suppress("UNCHECKED_CAST")
        val cloud = MadeUpValues(points.type, seed = 3).at(1_000_000_001) as MutableMap<String, Any?>
        cloud["points"] = (cloud["points"] as List<*>).toMutableList().apply { this[2] = 42 }
        val element = assertThrows(IllegalArgumentException::class.java) { points.encode(cloud, littleEndian = false) }
        assertEquals(
            "RTC::PointCloud.points[2]: expected a struct (a map of its members), got Integer 42",
            element.message,
        )
    }

    @Test
    fun `names in every form OpenRTM-aist writes them`() {
        val id = StandardDataTypes.named("IDL:RTC/RangeData:1.0")
        assertTrue(id is IdlType.Struct)
        assertEquals(id, StandardDataTypes.named("RangeData"))
        assertEquals(id, StandardDataTypes.named("RTC::RangeData"))
        assertNull(StandardDataTypes.named("IDL:Acme/Scan:1.0"))
        assertNull(StandardDataTypes.named("NoSuchType"))
        assertNull(StandardDataTypes.named("RTC::PortService"), "an interface is no data type")
    }

    @Test
    fun `made-up values change over time and stay plausible`() {
        val scans = MadeUpValues(StandardDataTypes.named("RangeData")!!, seed = 3)
        val first = scans.at(1_000_000_000) as Map<*, *>
        val second = scans.at(1_010_000_000) as Map<*, *>
        val ranges = first["ranges"] as DoubleArray
        val config = first["config"] as Map<*, *>
        assertEquals(1081, ranges.size)
        assertTrue(ranges.all { it >= config["minRange"] as Double && it <= config["maxRange"] as Double })
        assertNotEquals(ranges.toList(), (second["ranges"] as DoubleArray).toList())
        assertEquals(mapOf("sec" to 1L, "nsec" to 10_000_000L), second["tm"])
        assertEquals(comparable(first), comparable(scans.at(1_000_000_000)), "the same time gives the same sample")
        assertEquals(first["geometry"], second["geometry"], "a mounted scanner stays where it is")
        assertEquals(config, second["config"])
        assertThrows(UnsupportedOperationException::class.java) {
            @Suppress("UNCHECKED_CAST")
            (second["config"] as MutableMap<String, Any?>)["maxRange"] = 1.0
        }
    }

    /** Values as decoding gives them: every array a list, every number widened as its type reads. */
    private fun comparable(value: Any?): Any? =
        when (value) {
            is Map<*, *> -> value.mapValues { comparable(it.value) }
            is DoubleArray -> value.toList()
            is ByteArray -> value.toList()
            is List<*> -> value.map(::comparable)
            is Int -> value.toLong()
            is Short -> value.toLong()
            is java.math.BigInteger -> value.toLong()
            else -> value
        }
}
