package org.rtcoord.cli

import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.runPeer

/** `del`: dead registrations go, live objects stay; `ls` and rtls show the zombie before. */
class DelCommandTest {
    private val localisation = Localisation()
    private val doomed = localisation.path("doomed0.rtc")

    @AfterEach fun stop() = localisation.close()

    /** A component in another process bound in the naming service, then killed: its registration stays. */
    private fun zombie() {
        FixtureProcess.start("--naming", localisation.naming.address, "--scenario", "component:doomed0").kill()
    }

    @Test
    fun `a zombie is shown with a star and can be removed`() {
        zombie()
        assertEquals(
            "manager.mgr/\nlaser0.rtc\ngyro0.rtc\nodometry0.rtc\nlaser_localise0.rtc\n*doomed0.rtc\n",
            runRtcoord("ls", localisation.host).ok(),
        )
        assertTrue(
            runRtcoord("ls", "-l", localisation.host).ok().endsWith("\n-       -    -    -    -    *doomed0.rtc\n")
        )
        assertEquals("-  -  -  -  -  *doomed0.rtc\n", runRtcoord("ls", "-l", doomed).ok())
        assertEquals("$doomed\n", runRtcoord("find", localisation.host, "--type", "zombie").ok())
        assertEquals(
            runPeer("rtls", "-l", localisation.host).ok().output,
            runRtcoord("ls", "-l", localisation.host).ok(),
        )

        runRtcoord("del", doomed).ok()
        assertEquals(
            "manager.mgr/\nlaser0.rtc\ngyro0.rtc\nodometry0.rtc\nlaser_localise0.rtc\n",
            runRtcoord("ls", localisation.host).ok(),
        )
    }

    @Test
    fun `a live component among zombies is refused and nothing is removed`() {
        zombie()
        val line = runRtcoord("del", doomed, localisation.path("laser0.rtc")).failure()
        assertEquals("rtcoord: ${localisation.path("laser0.rtc")}: is a live component, not a zombie", line)
        assertTrue("*doomed0.rtc" in runRtcoord("ls", localisation.host).ok())
    }

    @Test
    fun `cat of a zombie says why it is dead`() {
        zombie()
        assertTrue(runRtcoord("cat", doomed).failure().startsWith("rtcoord: $doomed: unreachable ("))
    }
}
