package org.rtcoord.cli

import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/** `exit`: components finalise and leave naming; a bad path stops every one of them. */
class ExitCommandTest {
    private val localisation = Localisation()

    @AfterEach fun stop() = localisation.close()

    @Test
    fun `exited components finalise and leave naming`() {
        val leaving = listOf("odometry0", "gyro0").map { localisation.system.component(it) }
        runRtcoord("exit", localisation.path("odometry0.rtc"), localisation.path("gyro0.rtc")).ok()
        assertTrue(leaving.all { it.isExited })
        // Gone from naming when exit returns: ls right after shows no zombie.
        assertEquals("manager.mgr/\nlaser0.rtc\nlaser_localise0.rtc\n", runRtcoord("ls", localisation.host).ok())
    }

    @Test
    fun `one bad path among good ones exits none`() {
        runRtcoord("exit", localisation.path("odometry0.rtc"), localisation.path("manager.mgr")).failure()
        assertFalse(localisation.system.component("odometry0").isExited)
    }
}
