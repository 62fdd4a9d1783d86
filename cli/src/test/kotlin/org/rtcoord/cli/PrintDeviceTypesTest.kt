package org.rtcoord.cli

import java.nio.file.Paths
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.sim.SimulatedSystem

/** `print` on a simulated robot whose sensors send OpenRTM-aist's device types: each decoded, member by member. */
class PrintDeviceTypesTest {
    private val system = SimulatedSystem.start(Paths.get(javaClass.getResource("/devices.xml")!!.toURI()))

    @AfterEach fun stop() = system.close()

    private fun path(port: String) = "/${system.address}/${RuntimeProcess.hostContext}/$port"

    @Test
    fun `a pose prints as its class, a scan by its first ranges and its length, an image and a cloud member by member`() {
        val pose = runRtcoord("print", path("odometry0.rtc:odo"), "--count", "1").ok().trim()
        assertTrue(
            Regex("""\S+Z  TimedPose2D  TimedPose2D\(time=\S+, x=\S+, y=\S+, heading=\S+\)""").matches(pose),
            pose,
        )

        val scan = runRtcoord("print", path("ranger0.rtc:range"), "--count", "1").ok().trim()
        assertTrue(
            Regex(
                    """\S+Z  RangeData  \{ranges: \[(\d+\.\d+ ){7}\d+\.\d+ \.\.\. \(1081 values\)], geometry: \{.*}, config: \{minAngle: -2\.35\d*, .*maxRange: 30\.0, .*}}"""
                )
                .matches(scan),
            scan,
        )

        val image = runRtcoord("print", path("camera0.rtc:image"), "--count", "1").ok().trim()
        assertTrue(
            image.contains("  CameraImage  {width: 160, height: 120, bpp: 24, format: \"\", fDiv: 1.0, pixels: ["),
            image,
        )
        assertTrue(image.endsWith("... (57600 values)]}"), image)

        val cloud = runRtcoord("print", path("cloud0.rtc:cloud"), "--count", "1").ok().trim()
        assertTrue(cloud.contains("  PointCloud  {points: [{point: {x: "), cloud)
        assertTrue(cloud.contains("... (100 values)]"), cloud)
    }

    @Test
    fun `--json gives a scan whole`() {
        val json = runRtcoord("print", path("ranger0.rtc:range"), "--count", "1", "--json").ok().trim()
        assertTrue(json.startsWith("""{"time":""""), json)
        assertTrue(json.contains(""""type":"RangeData","value":{"ranges":["""), json)
        val ranges = Regex(""""ranges":\[([^\]]*)]""").find(json)!!.groupValues[1].split(',')
        assertEquals(1081, ranges.size)
        assertTrue(json.contains(""""config":{"minAngle":"""), json)
    }
}
