package org.rtcoord.internal

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test

class HandleMapTest {
    @Test
    fun `values keep the order their handles were first put in, and a replaced one keeps its place`() {
        val map = HandleMap<String>()
        map[1000] = "participating"
        map[0] = "owned"
        map[1000] = "participating again"
        assertEquals(listOf("participating again", "owned"), map.values())
        assertEquals("owned", map[0])
        assertNull(map[1])
        assertEquals("made", map.getOrPut(1) { "made" })
        assertEquals("made", map.getOrPut(1) { "made twice" })
        val seen = mutableListOf<Pair<Int, String>>()
        map.forEach { handle, value -> seen += handle to value }
        assertEquals(listOf(1000 to "participating again", 0 to "owned", 1 to "made"), seen)
    }

    @Test
    fun `retain forgets the handles it rejects and keeps the others in order`() {
        val map = HandleMap<Long>()
        listOf(0, 1, 1000, 1001).forEach { map[it] = it * 10L }
        map.retain { it != 1 && it != 1001 }
        assertEquals(2, map.size)
        assertEquals(listOf(0L, 10_000L), map.values())
        assertNull(map[1])
    }
}
