package org.rtcoord.profile

import kotlin.time.measureTimedValue
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.LifeCycle
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/** Save, restore, check and start on the 200-component pipeline (relays in nested naming contexts). */
class LargeSystemProfileTest {
    @Test
    fun `save, restore, check and start work on 200 components`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            Scenarios.pipeline(naming.corbaloc, COUNT).use {
                RtcTree(TreeConfig(nameServers = listOf(naming.address))).use { tree ->
                    val profiles = SystemProfiles(tree)
                    val (saved, saving) = measureTimedValue { profiles.save() }
                    assertEquals(COUNT, saved.components.size)
                    assertEquals(COUNT - 1, saved.dataPortConnectors.size)
                    assertEquals(emptyList<ProfileDifference>(), profiles.check(saved, LifeCycle.INACTIVE))

                    assertEquals(COUNT - 1, profiles.teardown(saved).size)
                    tree.componentNamed("relay7").setParameter("fail", "1", "default")
                    val disturbed = profiles.check(saved, state = null)
                    assertTrue(
                        disturbed.size >= COUNT && disturbed.any { it.subject.endsWith("relay7.rtc default.fail") },
                        disturbed.takeLast(3).toString(),
                    )
                    val (report, restoring) = measureTimedValue { profiles.restore(saved) }
                    assertEquals(
                        COUNT - 1,
                        report.done.count { it.startsWith("connected ") },
                        report.done.take(5).toString(),
                    )
                    assertTrue(report.done.any { it.endsWith("set fail in 'default'") }, report.done.toString())
                    assertEquals(emptyList<ProfileDifference>(), profiles.check(saved, state = null))
                    assertEquals(emptyList<String>(), profiles.restore(saved).done)

                    val (started, starting) = measureTimedValue { profiles.run(saved, OrderedAction.START) }
                    assertEquals(emptyList<StepOutcome>(), started.filter { !it.done })
                    val (differences, checking) = measureTimedValue { profiles.check(saved) }
                    assertEquals(emptyList<ProfileDifference>(), differences)
                    println("$COUNT components: save $saving, restore $restoring, start $starting, check $checking")
                }
            }
        }
    }

    private companion object {
        const val COUNT = 200
    }
}
