package org.rtcoord.cli

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test

/** The small text formats: aligned columns. */
class TextFormatsTest {
    @Test
    fun `columns are padded to the widest cell, the last one left as it is`() {
        assertEquals(
            listOf("  a     1", "  long  22  x"),
            aligned(listOf(listOf("a", "1"), listOf("long", "22", "x")), "  "),
        )
        assertEquals(listOf("key", "k    v"), aligned(listOf(listOf("key", ""), listOf("k", "v"))))
    }
}
