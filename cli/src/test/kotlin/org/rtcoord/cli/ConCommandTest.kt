package org.rtcoord.cli

import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.runPeer

/** `con`: a connector with the given name, id and properties, or a refusal before anything changes. */
class ConCommandTest {
    private val localisation = Localisation()
    private val laser = localisation.path("laser0.rtc:laser")
    private val localiser = localisation.path("laser_localise0.rtc:laser")

    @AfterEach fun stop() = localisation.close()

    @Test
    fun `ports connected already are refused with one line, as OpenRTM-aist refuses them, and nothing changes`() {
        val existing =
            localisation.system
                .component("laser0")
                .ref
                .get_ports()
                .single()
                .get_connector_profiles()
                .single()
                .connector_id
        val line = runRtcoord("con", laser, localiser).failure()
        assertEquals(
            "rtcoord: $laser: connect refused: already connected to $localiser (connector $existing); --allow-duplicate connects them again",
            line,
        )
        // The other way round, and with other properties, it is the same connection.
        assertTrue(
            "already connected" in runRtcoord("con", localiser, laser, "-p", "dataport.subscription_type=new").failure()
        )
        assertEquals(
            1,
            Regex("Connected to").findAll(runPeer("rtcat", "-l", localisation.path("laser0.rtc")).ok().output).count(),
        )
    }

    @Test
    fun `--allow-duplicate connects connected ports again, with a name, an id and properties, and prints the connector id`() {
        val id =
            runRtcoord(
                    "con",
                    laser,
                    localiser,
                    "--allow-duplicate",
                    "--name",
                    "second",
                    "--id",
                    "c2",
                    "-p",
                    "dataport.subscription_type=new",
                )
                .ok()
                .trim()
        assertEquals("c2", id)
        val shown = runRtcoord("cat", "-l", laser).ok()
        assertTrue(Regex("""connector +second\n +id +c2\n""").containsMatchIn(shown), shown)
        assertTrue(Regex("""id +c2\n(.*\n)*? +dataport\.subscription_type +new\n""").containsMatchIn(shown), shown)
        assertEquals(
            2,
            Regex("Connected to").findAll(runPeer("rtcat", "-l", localisation.path("laser0.rtc")).ok().output).count(),
        )
    }

    @Test
    fun `--json gives the connector`() {
        val json = runRtcoord("--json", "con", laser, localiser, "--allow-duplicate", "--id", "c3").ok()
        assertTrue(json.startsWith("{\n  \"id\": \"c3\",\n  \"name\": \"laser0.laser_laser_localise0.laser\",\n"), json)
    }

    @Test
    fun `incompatible ports are refused and nothing is connected`() {
        val gyro = localisation.path("gyro0.rtc:gyro")
        val line = runRtcoord("con", gyro, localiser).failure()
        assertEquals(
            "rtcoord: $gyro: connect rejected: incompatible data types: $gyro carries IDL:RTC/TimedDouble:1.0, $localiser carries IDL:RTC/TimedDoubleSeq:1.0",
            line,
        )
        assertEquals(
            "Active  1/0  0/0  1/0  0/0  gyro0.rtc\n",
            runRtcoord("ls", "-l", localisation.path("gyro0.rtc")).ok(),
        )
    }

    @Test
    fun `a property that is not KEY=VALUE is a usage error`() {
        runRtcoord("con", laser, localiser, "-p", "push").usageError()
    }
}
