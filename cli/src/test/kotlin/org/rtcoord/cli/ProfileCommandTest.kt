package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/** `profile save|restore|check|start|stop|teardown` on the localisation system. */
class ProfileCommandTest {
    private val localisation = Localisation()

    @AfterEach fun stop() = localisation.close()

    @Test
    fun `save, teardown, check, restore and check again`(@TempDir dir: Path) {
        val file = dir.resolve("sys.yaml").toString()
        runRtcoord("-n", localisation.naming.address, "profile", "save", "-o", file).ok()
        assertTrue(Files.readString(dir.resolve("sys.yaml")).startsWith("rtsProfile:"))
        assertEquals("", runRtcoord("profile", "check", file).ok())
        assertEquals(2, runRtcoord("profile", "teardown", file).ok().lines().count { it.startsWith("disconnected") })
        val check = runRtcoord("profile", "check", file)
        assertEquals(1, check.statusCode)
        assertEquals(2, check.stdout.lines().count { "expected a connection, found none" in it }, check.stdout)
        assertEquals("rtcoord: 2 difference(s) from the profile", check.stderr.trim())
        assertEquals(2, runRtcoord("profile", "restore", file).ok().lines().count { it.startsWith("connected") })
        assertTrue(
            runRtcoord("profile", "restore", file).ok().startsWith("nothing to change (2 connections already there)")
        )
        assertEquals("[]", runRtcoord("--json", "profile", "check", file).ok().trim())
    }

    @Test
    fun `restore --create makes a deleted component through its manager, and without it one line says what is missing`(
        @TempDir dir: Path
    ) {
        val file = dir.resolve("sys.xml").toString()
        runRtcoord("-n", localisation.naming.address, "profile", "save", "-o", file).ok()
        runRtcoord("mgr", localisation.path("manager.mgr"), "delete", "laser_localise0").ok()
        val localiser = localisation.path("laser_localise0.rtc")
        assertEquals(
            "rtcoord: $file: nothing changed: required component $localiser is not running",
            runRtcoord("profile", "restore", file).failure(),
        )
        val restored = runRtcoord("profile", "restore", "--create", file).ok().lines()
        assertEquals(
            "created $localiser (laser_localise) through ${localisation.path("manager.mgr")}",
            restored.first(),
        )
        assertEquals(2, restored.count { it.startsWith("connected") }, restored.toString())
        assertEquals("", runRtcoord("profile", "check", "--state", "any", file).ok())
    }

    @Test
    fun `ConfigSample's profile restores onto it unchanged, a value written outside its constraint warns, and --strict refuses it`(
        @TempDir dir: Path
    ) {
        val naming = NamingService.start()
        Scenarios.configSample(naming.corbaloc).use {
            val file = dir.resolve("s.xml").toString()
            val sample = "/${naming.address}/${RuntimeProcess.hostContext}/ConfigSample0.rtc"
            runRtcoord("-n", naming.address, "profile", "save", "-o", file).ok()
            assertEquals(
                "nothing to change (0 connections already there)\n",
                runRtcoord("-n", naming.address, "profile", "restore", "--strict", file).ok(),
            )

            runRtcoord("-n", naming.address, "conf", sample, "set", "--set", "mode0", "int_param0", "100").ok()
            val refused = runRtcoord("-n", naming.address, "profile", "restore", "--strict", file).failure()
            assertEquals(
                "rtcoord: $file: nothing changed: $sample: configuration set 'mode0': int_param0: '12345' is outside 0<=x<=150",
                refused,
            )
            val restored = runRtcoord("-n", naming.address, "profile", "restore", file)
            assertEquals(0, restored.statusCode, restored.stderr)
            assertEquals(
                "rtcoord: warning: $sample: configuration set 'mode0': int_param0: '12345' is outside 0<=x<=150\n",
                restored.stderr,
            )
            assertEquals("$sample: set int_param0 in 'mode0'\n", restored.stdout)
            assertEquals("", runRtcoord("-n", naming.address, "profile", "check", "--state", "any", file).ok())
        }
        naming.close()
    }

    @Test
    fun `a bad file is one line naming file and line, and start --dry-run prints the plan`(@TempDir dir: Path) {
        val bad = dir.resolve("bad.xml")
        Files.writeString(
            bad,
            "<?xml version=\"1.0\"?>\n<rts:RtsProfile xmlns:rts=\"http://www.openrtp.org/namespaces/rts\">\n</rts:RtsProfile>\n",
        )
        assertEquals(
            "rtcoord: $bad:2: rts:RtsProfile has no rts:id",
            runRtcoord("profile", "check", bad.toString()).failure(),
        )
        val file = dir.resolve("sys.xml").toString()
        runRtcoord("-n", localisation.naming.address, "profile", "save", "-o", file).ok()
        val plan = runRtcoord("profile", "start", "--dry-run", file).ok().lines().filter { it.isNotEmpty() }
        assertEquals(4, plan.size, plan.toString())
        assertTrue(
            plan.all { it.startsWith("0 /${localisation.naming.address}/") && it.endsWith(" context 0") },
            plan.toString(),
        )
        val stopped = runRtcoord("profile", "stop", file).ok()
        assertEquals(4, stopped.lines().count { it.startsWith("done at") }, stopped)
        assertEquals(
            4,
            runRtcoord("profile", "check", "--state", "active", file).stdout.lines().count {
                "expected ACTIVE, found INACTIVE" in it
            },
        )
    }
}
