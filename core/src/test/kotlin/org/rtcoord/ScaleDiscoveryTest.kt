package org.rtcoord

import kotlin.time.Duration.Companion.seconds
import kotlin.time.measureTime
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

class ScaleDiscoveryTest {
    @Test
    fun `a thousand components are discovered completely`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            Scenarios.scale(naming.corbaloc, 1000).use {
                RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                    val elapsed = measureTime { tree.refresh() }
                    println("discovered 1000 components with full profiles in $elapsed")
                    val components = tree.find { it is ComponentNode }.toList().map { it as ComponentNode }
                    assertEquals(1000, components.size)
                    assertEquals(
                        (0 until 1000).map { "relay$it" }.toSet(),
                        components.map { it.snapshots.value!!.instanceName }.toSet(),
                    )
                    assertTrue(
                        components.all { node ->
                            node.snapshots.value!!.let {
                                it.ports.size == 3 && it.contexts.single().state == LifeCycle.INACTIVE
                            }
                        }
                    )
                }
            }
        }
    }

    @Test
    fun `a hung servant and a dead registration do not hold up discovery`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            Scenarios.scale(naming.corbaloc, 200).use { system ->
                FixtureProcess.start("--naming", naming.address, "--scenario", "component:dead0").kill()
                system.component("relay42").hang()
                try {
                    RtcTree(TreeConfig(listOf(naming.address), callTimeout = 1.seconds)).use { tree ->
                        val elapsed = measureTime { tree.refresh() }
                        println("discovered 200 components, one hung and one dead, in $elapsed (deadline 1 s)")
                        assertTrue(elapsed < 3.seconds, "discovery took $elapsed")

                        val nodes = tree.find().toList()
                        val hung = nodes.single { it.name == "relay42.rtc" }
                        val dead = nodes.single { it.name == "dead0.rtc" }
                        assertTrue(hung is ZombieNode && hung.cause is TimedOutException, hung.toString())
                        assertTrue(dead is ZombieNode && dead.cause is UnreachableException, dead.toString())
                        val complete = nodes.filterIsInstance<ComponentNode>()
                        assertEquals(199, complete.size)
                        assertTrue(complete.all { it.snapshots.value?.ports?.size == 3 })
                    }
                } finally {
                    system.component("relay42").release()
                }
            }
        }
    }
}
