package org.rtcoord.dsl

import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.LifeCycle
import org.rtcoord.fixtures.await
import org.rtcoord.profile.ProfileDifference
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.profile.SystemProfiles

/** RTSProfiles in scripts: a mode's network from a profile, and restoring and checking a profile as actions. */
class ProfileDslTest : CoordinatedSystem() {
    @TempDir lateinit var directory: Path

    override val scriptDirectory: Path
        get() = directory

    /** The running system saved as [name] in the script's directory. */
    private suspend fun saved(name: String, change: (RtsProfile) -> RtsProfile = { it }): RtsProfile {
        val profile = change(SystemProfiles(witness).save())
        Files.writeString(directory.resolve(name), RtsProfiles.write(profile, RtsProfiles.formatOf(name, "")))
        return profile
    }

    @Test
    fun `a mode's network taken from a profile brings back its states, connections and active sets`(): Unit =
        runBlocking {
            val profile = saved("nav.yaml")
            val localiser = witness.component(path("laser_localise0.rtc"))
            localiser.disconnectAll()
            localiser.activateConfigurationSet("precise")
            witness.component(path("laser0.rtc")).deactivate()
            assertEquals(4, SystemProfiles(witness).check(profile).size)
            coordinator {
                modes("m") {
                    initial("navigating")
                    mode("navigating") {
                        network { profile("nav.yaml") }
                        on(done) goTo "running"
                    }
                    mode("running")
                }
            }
                .use { coordinator ->
                    coordinator.start()
                    val machine = coordinator.machine("m")
                    await("the profile's network to be done") { machine.mode.value == "m/running" }
                    assertEquals(emptyList<ProfileDifference>(), SystemProfiles(witness).check(profile))
                    assertEquals(2, log.count { it.startsWith("connect ") }, log.toString())
                    assertTrue(log.any { it.startsWith("activate configuration set default") }, log.toString())
                }
        }

    @Test
    fun `restoreProfile and checkProfile are actions, and a refused restore changes nothing and is one failed action`():
        Unit = runBlocking {
        val profile = saved("sys.xml")
        saved("bad.xml") { p ->
            p.withComponents(
                p.components.map { c ->
                    if (c.instanceName != "laser_localise0") c
                    else
                        c.withConfigurationSets(
                            c.configurationSets.map {
                                if (it.id == "default") it.withData(it.data + ("gain" to "99")) else it
                            }
                        )
                }
            )
        }
        val localiser = witness.component(path("laser_localise0.rtc"))
        localiser.disconnectAll()
        localiser.setParameter("gain", "3.0", "default")
        localiser.activateConfigurationSet("default")
        val checks = CopyOnWriteArrayList<List<ProfileDifference>>()
        coordinator {
            after(10.milliseconds) {
                attempt { restoreProfile("bad.xml", strict = true) }
                checks += checkProfile("sys.xml", state = null)
                val report = restoreProfile("sys.xml")
                log("restored: ${report.done.size} changes")
                checks += checkProfile("sys.xml")
            }
        }
            .use { coordinator ->
                coordinator.start()
                await("the timer to check twice") { checks.size == 2 }
                assertEquals(3, checks[0].size, checks[0].toString())
                assertEquals(emptyList<ProfileDifference>(), checks[1])
                val failed = coordinator.failedActions.single()
                assertEquals("restore profile bad.xml", failed.action)
                assertTrue("'99' is outside 0<x<10" in failed.reason && '\n' !in failed.reason, failed.reason)
                assertTrue(
                    log.contains("restore profile sys.xml") && log.any { it.startsWith("  connected ") },
                    log.toString(),
                )
                assertEquals(LifeCycle.ACTIVE, localiser.state())
            }
    }
}
