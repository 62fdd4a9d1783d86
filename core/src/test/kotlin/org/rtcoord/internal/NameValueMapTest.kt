package org.rtcoord.internal

import _SDOPackage.NameValue
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertSame
import org.junit.jupiter.api.Test
import org.omg.CORBA.ORB

class NameValueMapTest {
    private val orb = ORB.init()

    private fun nameValue(name: String, value: String) =
        NameValue(name, orb.create_any().apply { insert_string(value) })

    @Test
    fun `a name-value list reads as the map it was read into before, in its order`() {
        val list =
            arrayOf(
                nameValue("port.port_type", "DataOutPort"),
                nameValue("dataport.data_type", "IDL:RTC/TimedLong:1.0"),
                nameValue("dataport.interface_type", "corba_cdr"),
            )
        val map = list.toMap()
        val expected =
            linkedMapOf(
                "port.port_type" to "DataOutPort",
                "dataport.data_type" to "IDL:RTC/TimedLong:1.0",
                "dataport.interface_type" to "corba_cdr",
            )
        assertEquals(expected, map)
        assertEquals(map, expected)
        assertEquals(expected.hashCode(), map.hashCode())
        assertEquals(expected.toList(), map.toList(), "in the list's order")
        assertEquals("corba_cdr", map["dataport.interface_type"])
        assertNull(map["dataport.dataflow_type"])
        assertFalse("dataport.dataflow_type" in map)
        assertEquals(expected.toString(), map.toString())
    }

    @Test
    fun `a name given twice keeps its first place and its last value, as a map filled in order does`() {
        val list = arrayOf(nameValue("a", "1"), nameValue("b", "2"), nameValue("a", "3"))
        assertEquals(listOf("a" to "3", "b" to "2"), list.toMap().toList())
        assertEquals(list.associate { it.name to it.value.extract_string() }.toList(), list.toMap().toList())
    }

    @Test
    fun `names and short values read twice are the same strings`() {
        val long = "IOR:" + "0".repeat(200)
        val first = arrayOf(nameValue(String(charArrayOf('k')), "IDL:RTC/TimedLong:1.0"), nameValue("ior", long))
        val second = arrayOf(nameValue(String(charArrayOf('k')), "IDL:RTC/TimedLong:1.0"), nameValue("ior", long))
        val a = first.toMap()
        val b = second.toMap()
        assertSame(a.keys.first(), b.keys.first())
        assertSame(a["k"], b["k"])
        assertEquals(long, a["ior"])
    }
}
