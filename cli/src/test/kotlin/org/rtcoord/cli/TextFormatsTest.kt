package org.rtcoord.cli

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test

/** The small text formats: JSON and aligned columns. */
class TextFormatsTest {
    @Test
    fun `JSON escapes strings and writes nested values`() {
        val value = mapOf("text" to "a \"quoted\" \\ path\n\t\u0001", "list" to listOf(1, 2.5, true, null), "empty" to emptyMap<String, Any>())
        assertEquals(
            "{\n  \"text\": \"a \\\"quoted\\\" \\\\ path\\n\\t\\u0001\",\n  \"list\": [\n    1,\n    2.5,\n    true,\n    null\n  ],\n  \"empty\": {}\n}",
            toJson(value),
        )
        assertEquals("{\"a\":[1,\"b\"],\"c\":[]}", toJson(mapOf("a" to listOf(1, "b"), "c" to emptyList<Any>()), pretty = false))
    }

    @Test
    fun `columns are padded to the widest cell, the last one left as it is`() {
        assertEquals(listOf("  a     1", "  long  22  x"), aligned(listOf(listOf("a", "1"), listOf("long", "22", "x")), "  "))
        assertEquals(listOf("key", "k    v"), aligned(listOf(listOf("key", ""), listOf("k", "v"))))
    }
}
