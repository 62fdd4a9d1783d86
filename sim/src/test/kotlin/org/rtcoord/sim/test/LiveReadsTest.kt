package org.rtcoord.sim.test

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test
import org.rtcoord.LifeCycle
import org.rtcoord.NamingDirectory
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.sim.SimulatedSystem
import org.rtcoord.sim.savedLocalisation

/** What a test reads of the system as it is now, for components no event has told of yet. */
class LiveReadsTest {
    @Test
    fun `a component the system has but naming does not show yet is not there, not an error`() {
        SimulatedSystem.start(savedLocalisation()).use { sim ->
            RtcTree(TreeConfig(nameServers = listOf(sim.address))).use { tree ->
                runBlocking {
                    val reads = LiveReads(sim, tree, null, emptyList())
                    assertEquals(LifeCycle.ACTIVE, reads.state("laser0"))
                    // As between a manager making a component and binding its name, as a coordinator's invariant
                    // may read it.
                    val context = "/${sim.address}/${sim.component("laser0").contexts.joinToString("/")}"
                    (tree.node(context) as NamingDirectory).unbind("laser0.rtc")
                    assertNull(reads.state("laser0"))
                    assertFalse(reads.exists("laser0"))
                    assertNull(reads.state("nothing0"))
                }
            }
        }
    }
}
