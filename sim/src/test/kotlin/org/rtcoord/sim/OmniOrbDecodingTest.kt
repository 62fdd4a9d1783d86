package org.rtcoord.sim

import java.nio.file.Paths
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.datatypes.DataCodec
import org.rtcoord.datatypes.MadeUpValues
import org.rtcoord.datatypes.StandardDataTypes
import org.rtcoord.fixtures.Peers

/**
 * What the simulation sends, read by code nobody here wrote: omniORB's `cdrUnmarshal`, which OpenRTM-aist-Python's
 * `CORBA_CdrMemoryStream` calls to read every sample, with rtctree's stubs of OpenRTM-aist's data types. Each type in
 * both byte orders.
 */
class OmniOrbDecodingTest {
    private val time = 1_700_000_000_250_000_000

    @Test
    fun `omniORB reads the device types the simulation encodes, in both byte orders`() {
        val types = listOf("TimedPose2D", "RangeData", "CameraImage", "PointCloud", "GPSData", "ActArrayState")
        val input = types.flatMap { name ->
            val codec = DataCodec(StandardDataTypes.named(name)!!)
            val value = MadeUpValues(codec.type, seed = name.hashCode()).at(time)
            listOf(true, false).map { little ->
                "$name ${if (little) "little" else "big"} ${codec.encode(value, little).joinToString("") { "%02x".format(it) }}"
            }
        }
        val output = python(input)
        val expected = types.flatMap { name ->
            val value = MadeUpValues(StandardDataTypes.named(name)!!, seed = name.hashCode()).at(time) as Map<*, *>
            val summary = summary(name, value)
            listOf("$name little $summary", "$name big $summary")
        }
        assertEquals(expected, output)
    }

    private fun summary(name: String, value: Map<*, *>): String =
        when (name) {
            "TimedPose2D" -> {
                val pose = value["data"] as Map<*, *>
                val position = pose["position"] as Map<*, *>
                "x=${fixed(position["x"])} y=${fixed(position["y"])} heading=${fixed(pose["heading"])} sec=1700000000"
            }
            "RangeData" -> "ranges=1081 first=${fixed((value["ranges"] as DoubleArray)[0])} maxRange=${fixed(30.0)}"
            "CameraImage" -> "width=160 height=120 bpp=24 pixels=57600"
            "PointCloud" ->
                "points=100 z=${fixed((((value["points"] as List<*>)[0] as Map<*, *>)["point"] as Map<*, *>)["z"])}"
            "GPSData" -> "fix=${value["fixType"]} satellites=${value["numSatellites"]}"
            "ActArrayState" -> "actuators=4 status=${((value["actuators"] as List<*>)[0] as Map<*, *>)["status"]}"
            else -> error(name)
        }

    /** Nine decimals, as Python's `%.9f` writes them: both round the exact binary value. */
    private fun fixed(value: Any?): String = "%.9f".format(java.util.Locale.ROOT, value as Double)

    private fun python(lines: List<String>): List<String> {
        val script = Paths.get(javaClass.getResource("/omniorb/decode.py")!!.toURI())
        val process =
            ProcessBuilder(Peers.require("python").toString(), script.toString()).redirectErrorStream(true).start()
        process.outputStream.bufferedWriter().use { writer ->
            lines.forEach {
                writer.write(it)
                writer.newLine()
            }
        }
        val output = process.inputStream.bufferedReader().readLines()
        check(process.waitFor(60, TimeUnit.SECONDS)) { "python did not finish" }
        assertEquals(0, process.exitValue(), output.joinToString("\n"))
        return output
    }
}
