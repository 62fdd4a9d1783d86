package org.rtcoord.cli

import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/** `mgr`: creating and deleting components, loading modules, listing what a manager has. */
class MgrCommandTest {
    private val localisation = Localisation()
    private val master = localisation.path("manager.mgr")
    private val slave = localisation.path("manager.mgr/manager_slave")

    @AfterEach fun stop() = localisation.close()

    @Test
    fun `creates a component where naming shows it, and deletes it again`() {
        assertEquals(
            "${localisation.path("odo_localise0.rtc")}\n",
            runRtcoord("mgr", master, "create", "odo_localise").ok(),
        )
        assertEquals(
            "${localisation.path("spare.rtc")}\n",
            runRtcoord("mgr", master, "create", "odo_localise", "--name", "spare").ok(),
        )
        assertTrue("odo_localise0.rtc" in runRtcoord("ls", localisation.host).ok())
        runRtcoord("mgr", master, "delete", "odo_localise0").ok()
        runRtcoord("mgr", slave, "delete", "spare").ok()
        // Gone from naming when delete returns: no zombie left for ls to show.
        assertEquals(
            "manager.mgr/\nlaser0.rtc\ngyro0.rtc\nodometry0.rtc\nlaser_localise0.rtc\n",
            runRtcoord("ls", localisation.host).ok(),
        )
    }

    @Test
    fun `lists hosted components, modules and factories`() {
        val components =
            listOf("laser0", "gyro0", "odometry0", "laser_localise0").joinToString("") { "$slave/$it.rtc\n" }
        assertEquals(components, runRtcoord("mgr", master, "list").ok())
        assertEquals(components, runRtcoord("mgr", slave, "list", "components").ok())
        assertEquals("sensors.so\nlocalisers.so\n", runRtcoord("mgr", slave, "list", "loaded").ok())
        assertEquals(
            "PeriodicECSharedComposite\nlaser\ngyro\nodometry\nlaser_localise\n",
            runRtcoord("mgr", slave, "list", "factories").ok(),
        )
        assertEquals(
            "[\n  \"sensors.so\",\n  \"localisers.so\",\n  \"odo_localise.so\"\n]\n",
            runRtcoord("--json", "mgr", slave, "list", "modules").ok(),
        )
    }

    @Test
    fun `unloads and loads modules`() {
        runRtcoord("mgr", slave, "unload", "localisers.so").ok()
        assertEquals("sensors.so\n", runRtcoord("mgr", slave, "list", "loaded").ok())
        runRtcoord("mgr", slave, "load", "localisers.so").ok()
        assertEquals("sensors.so\nlocalisers.so\n", runRtcoord("mgr", slave, "list", "loaded").ok())
    }

    @Test
    fun `unknown types, components and modules are named`() {
        assertEquals(
            "rtcoord: $master: create 'sonar' failed: nil (the manager created none; " +
                "factories: PeriodicECSharedComposite, gyro, laser, laser_localise, odometry; loadable modules: none)",
            runRtcoord("mgr", master, "create", "sonar").failure(),
        )
        assertEquals(
            "rtcoord: $master: no component 'sonar0' is hosted by this manager or its slaves",
            runRtcoord("mgr", master, "delete", "sonar0").failure(),
        )
        assertTrue(
            runRtcoord("mgr", slave, "load", "missing.so")
                .failure()
                .startsWith("rtcoord: $slave: load module 'missing.so' rejected")
        )
        runRtcoord("mgr", master).usageError()
        runRtcoord("mgr", master, "list", "everything").usageError()
    }
}
