package org.rtcoord

import java.time.Instant
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNotEquals
import org.junit.jupiter.api.Test
import org.rtcoord.profile.Condition
import org.rtcoord.profile.Extension

/** Values are equal, hashed and printed by their fields, as the data classes they replace were. */
class ValueObjectTest {
    @Test
    fun `values of one class with equal fields are equal, hash alike and print their fields`() {
        val at = Instant.ofEpochSecond(1)
        assertEquals(TimedPoint2D(at, 1.0, 2.0), TimedPoint2D(at, 1.0, 2.0))
        assertEquals(TimedPoint2D(at, 1.0, 2.0).hashCode(), TimedPoint2D(at, 1.0, 2.0).hashCode())
        assertNotEquals(TimedPoint2D(at, 1.0, 2.0), TimedPoint2D(at, 1.0, 3.0))
        assertEquals("WaitTime(milliseconds=300)", Condition.WaitTime(300).toString())
        assertEquals(Extension(visible = true), Extension().withVisible(true))
    }

    @Test
    fun `values of two classes are not equal, even with equal fields`() {
        val handle: ContextSelector = ContextSelector.Handle(1)
        assertNotEquals(handle, ContextSelector.Index(1))
    }

    @Test
    fun `unknown data compares its bytes by content and prints their count`() {
        assertEquals(UnknownData("T", byteArrayOf(1, 2), true), UnknownData("T", byteArrayOf(1, 2), true))
        assertEquals(
            "UnknownData(typeName=T, bytes=2 bytes, littleEndian=true)",
            UnknownData("T", byteArrayOf(1, 2), true).toString(),
        )
    }
}
