package org.rtcoord.internal

import RTC.Time
import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.time.Instant
import java.util.Properties
import org.jacorb.orb.CDROutputStream
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CORBA.ORB
import org.rtcoord.StructuredData
import org.rtcoord.TimedDouble
import org.rtcoord.TimedDoubleSeq
import org.rtcoord.TimedLong
import org.rtcoord.TimedPose2D
import org.rtcoord.TimedString
import org.rtcoord.TimedVelocity2D
import org.rtcoord.UnknownData
import org.rtcoord.datatypes.DataCodec
import org.rtcoord.datatypes.StandardDataTypes
import org.rtcoord.internal.data.DataDecoder
import org.rtcoord.internal.data.DataTap

/** Decoding against JacORB's own CDR encoder (big-endian, from the compiled IDL) and hand-made little-endian bytes. */
class DataDecoderTest {
    private fun jacorb(write: (CDROutputStream) -> Unit): ByteArray {
        val out = CDROutputStream(orb)
        write(out)
        return out.bufferCopy
    }

    private val time = Time(1_700_000_000, 123_456_789)
    private val instant = Instant.ofEpochSecond(1_700_000_000, 123_456_789)

    @Test
    fun `big-endian samples encoded by JacORB from the IDL decode to their values`() {
        val double = jacorb { RTC.TimedDoubleHelper.write(it, RTC.TimedDouble(time, 2.5)) }
        assertEquals(
            TimedDouble(instant, 2.5),
            DataDecoder("IDL:RTC/TimedDouble:1.0", littleEndian = false).decode(double),
        )

        val seq = jacorb { RTC.TimedDoubleSeqHelper.write(it, RTC.TimedDoubleSeq(time, doubleArrayOf(1.0, 2.0, 3.5))) }
        assertEquals(
            TimedDoubleSeq(instant, listOf(1.0, 2.0, 3.5)),
            DataDecoder("TimedDoubleSeq", littleEndian = false).decode(seq),
        )

        val text = jacorb { RTC.TimedStringHelper.write(it, RTC.TimedString(time, "scan ok")) }
        assertEquals(
            TimedString(instant, "scan ok"),
            DataDecoder("RTC::TimedString", littleEndian = false).decode(text),
        )

        val long = jacorb { RTC.TimedLongHelper.write(it, RTC.TimedLong(time, -7)) }
        assertEquals(TimedLong(instant, -7), DataDecoder("IDL:RTC/TimedLong:1.0", littleEndian = false).decode(long))

        val pose = jacorb {
            RTC.TimedPose2DHelper.write(it, RTC.TimedPose2D(time, RTC.Pose2D(RTC.Point2D(1.0, 2.0), 0.5)))
        }
        assertEquals(
            TimedPose2D(instant, 1.0, 2.0, 0.5),
            DataDecoder("IDL:RTC/TimedPose2D:1.0", littleEndian = false).decode(pose),
        )

        val velocity = jacorb {
            RTC.TimedVelocity2DHelper.write(it, RTC.TimedVelocity2D(time, RTC.Velocity2D(0.1, 0.0, -0.2)))
        }
        assertEquals(
            TimedVelocity2D(instant, 0.1, 0.0, -0.2),
            DataDecoder("IDL:RTC/TimedVelocity2D:1.0", littleEndian = false).decode(velocity),
        )
    }

    @Test
    fun `every other standard type decodes member by member, and encodes to JacORB's bytes`() {
        val geometry =
            RTC.RangerGeometry(
                RTC.Geometry3D(
                    RTC.Pose3D(RTC.Point3D(0.1, 0.0, 0.3), RTC.Orientation3D(0.0, 0.0, 1.5)),
                    RTC.Size3D(0.05, 0.05, 0.07),
                ),
                emptyArray(),
            )
        val config = RTC.RangerConfig(-2.35, 2.35, 0.0043, 0.02, 30.0, 0.001, 40.0)
        val scan = RTC.RangeData(time, doubleArrayOf(1.0, 2.5, 29.9), geometry, config)
        val bytes = jacorb { RTC.RangeDataHelper.write(it, scan) }
        val decoded = DataDecoder("IDL:RTC/RangeData:1.0", littleEndian = false).decode(bytes) as StructuredData
        assertEquals(instant, decoded.time)
        assertEquals(listOf(1.0, 2.5, 29.9), decoded.member("ranges"))
        assertEquals(30.0, decoded.member("config.maxRange"))
        assertEquals(1.5, decoded.member("geometry.geometry.pose.orientation.y"))
        assertEquals(emptyList<Any>(), decoded.member("geometry.elementGeometries"))

        val codec = DataCodec(StandardDataTypes.named("RangeData")!!)
        assertEquals(
            bytes.toList(),
            codec.encode(decoded.members, littleEndian = false).toList(),
            "our encoder writes what JacORB writes",
        )

        val image = jacorb {
            RTC.CameraImageHelper.write(it, RTC.CameraImage(time, 2, 1, 24, "", 1.0, byteArrayOf(1, 2, 3, 4, 5, 6)))
        }
        val camera = DataDecoder("CameraImage", littleEndian = false).decode(image) as StructuredData
        assertEquals(listOf<Byte>(1, 2, 3, 4, 5, 6), camera.member("pixels"))
        assertEquals(24, camera.member("bpp"), "an unsigned short reads as an Int")
    }

    @Test
    fun `little-endian samples, as OpenRTM sends by default, decode with the sequence aligned from the first byte`() {
        val bytes =
            ByteBuffer.allocate(32)
                .order(ByteOrder.LITTLE_ENDIAN)
                .putInt(1_700_000_000)
                .putInt(123_456_789)
                .putInt(2)
                .putInt(0)
                .putDouble(1.25)
                .putDouble(-3.0)
                .array()
        assertEquals(
            TimedDoubleSeq(instant, listOf(1.25, -3.0)),
            DataDecoder("IDL:RTC/TimedDoubleSeq:1.0", littleEndian = true).decode(bytes),
        )
        val other = DataDecoder("IDL:RTC/TimedDoubleSeq:1.0", littleEndian = false).decode(bytes)
        assertTrue(other is UnknownData, "read in the wrong byte order the length exceeds the data: $other")
    }

    @Test
    fun `unknown types and malformed data arrive as the type name and the raw bytes`() {
        val bytes = byteArrayOf(1, 2, 3, 4, 5)
        val unknown = DataDecoder("IDL:Acme/Scan:1.0", littleEndian = true).decode(bytes) as UnknownData
        assertEquals("IDL:Acme/Scan:1.0", unknown.typeName)
        assertEquals(bytes.toList(), unknown.bytes.toList())
        assertEquals(null, unknown.time)
        val short = DataDecoder("TimedDouble", littleEndian = true).decode(bytes)
        assertEquals(UnknownData("TimedDouble", bytes, true), short)
    }

    @Test
    fun `the byte order is the first one the connector's endian property lists`() {
        assertTrue(DataTap.littleEndian("little,big"))
        assertTrue(DataTap.littleEndian(null))
        assertEquals(false, DataTap.littleEndian(" BIG , little"))
    }

    companion object {
        private val orb: ORB =
            ORB.init(
                emptyArray(),
                Properties().apply {
                    setProperty("org.omg.CORBA.ORBClass", "org.jacorb.orb.ORB")
                    setProperty("org.omg.CORBA.ORBSingletonClass", "org.jacorb.orb.ORBSingleton")
                },
            )

        @JvmStatic @AfterAll fun shutdown() = orb.destroy()
    }
}
