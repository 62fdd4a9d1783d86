package org.rtcoord.internal.logs

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.msgpack.core.MessagePack
import org.msgpack.core.MessagePackException

/** A frame is decoded only once it is whole: where it ends, from any prefix of it. */
class FrameExtentTest {
    private val frame =
        MessagePack.newDefaultBufferPacker()
            .apply {
                packArrayHeader(3).packString("rtc.forward").packArrayHeader(2)
                packArrayHeader(2).packLong(1).packMapHeader(1).packString("message").packString("x".repeat(300))
                packArrayHeader(2).packLong(2).packMapHeader(1).packString("message").packBinaryHeader(3)
                writePayload(byteArrayOf(1, 2, 3))
                packMapHeader(1).packString("chunk").packString("c")
            }
            .toByteArray()

    @Test
    fun `every prefix of a frame is not yet whole, and the frame with more after it ends where it ends`() {
        val extent = FrameExtent(limit = 1024)
        for (length in 0 until frame.size) assertEquals(-1, extent.lengthOf(frame, 0, length), "prefix of $length")
        val twice = byteArrayOf(7) + frame + frame
        assertEquals(frame.size, extent.lengthOf(twice, 1, twice.size - 1))
        assertEquals(frame.size, extent.lengthOf(twice, 1 + frame.size, frame.size))
    }

    @Test
    fun `a frame over the limit is refused from its bytes, and a declared size over it from the header alone`() {
        val refused = assertThrows<RefusedInput> { FrameExtent(limit = 100).lengthOf(frame, 0, frame.size) }
        assertEquals(ForwardRefusal.TOO_LARGE, refused.refusal)
        // [str 32 declaring 2 GiB]: nothing of it has come.
        val header = byteArrayOf(0x91.toByte(), 0xdb.toByte(), 0x7f, -1, -1, -1)
        val declared = assertThrows<RefusedInput> { FrameExtent(limit = 1024).lengthOf(header, 0, header.size) }
        assertEquals(ForwardRefusal.TOO_LARGE, declared.refusal)
    }

    @Test
    fun `bytes that are not MessagePack are msgpack-core's error`() {
        assertThrows<MessagePackException> { FrameExtent(limit = 1024).lengthOf(byteArrayOf(0xc1.toByte()), 0, 1) }
    }
}
