package org.rtcoord.cli

import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test

/** `dis`: between two ports, one connector by id, or everything on a port. */
class DisCommandTest {
    private val localisation = Localisation()
    private val laser = localisation.path("laser0.rtc:laser")
    private val localiser = localisation.path("laser_localise0.rtc:laser")

    @AfterEach fun stop() = localisation.close()

    private fun long(name: String) = runRtcoord("ls", "-l", localisation.path(name)).ok()

    @Test
    fun `between two ports`() {
        runRtcoord("dis", laser, localiser).ok()
        assertEquals("Active  1/0  0/0  1/0  0/0  laser0.rtc\n", long("laser0.rtc"))
        assertEquals("Active  3/1  2/1  1/0  0/0  laser_localise0.rtc\n", long("laser_localise0.rtc"))
    }

    @Test
    fun `one connector by id, leaving the others`() {
        runRtcoord("con", laser, localiser, "--allow-duplicate", "--id", "extra").ok()
        runRtcoord("dis", laser, "--id", "extra").ok()
        assertEquals(1, Regex("<-").findAll(runRtcoord("cat", localiser).ok()).count())
    }

    @Test
    fun `every connection of a port`() {
        runRtcoord("dis", localisation.path("laser_localise0.rtc:odo")).ok()
        runRtcoord("dis", localiser).ok()
        assertEquals("Active  3/0  2/0  1/0  0/0  laser_localise0.rtc\n", long("laser_localise0.rtc"))
    }

    @Test
    fun `ports that are not connected, or an unknown id, are errors`() {
        val gyro = localisation.path("gyro0.rtc:gyro")
        assertEquals("rtcoord: $laser: not connected to $gyro", runRtcoord("dis", laser, gyro).failure())
        assertEquals(
            "rtcoord: $laser: no connector 'nope' (connectors: ${connectorOf(laser)})",
            runRtcoord("dis", laser, "--id", "nope").failure(),
        )
        assertEquals("Active  1/1  0/0  1/1  0/0  laser0.rtc\n", long("laser0.rtc"))
    }

    private fun connectorOf(port: String): String =
        Regex("""\n +id +(\S+)\n""").find(runRtcoord("cat", "-l", port).ok())!!.groupValues[1]
}
