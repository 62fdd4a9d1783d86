package org.rtcoord

import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

class ConcurrentOperationsTest {
    @Test
    fun `many coroutines operate and read different nodes at once without deadlock or lost update`(): Unit =
        runBlocking {
            NamingService.start().use { naming ->
                Scenarios.scale(naming.corbaloc, 40).use {
                    RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                        tree.refresh()
                        val components = tree.find { it is ComponentNode }.toList().map { it as ComponentNode }
                        withTimeout(60.seconds) {
                            coroutineScope {
                                components.forEachIndexed { index, component ->
                                    launch(Dispatchers.Default) {
                                        repeat(3) {
                                            component.activate()
                                            component.deactivate()
                                        }
                                        component.activate()
                                        component.setParameter("fail", "0")
                                        component.addConfigurationSet("mine", mapOf("fail" to "$index"))
                                    }
                                }
                                repeat(10) { launch(Dispatchers.Default) { tree.refresh() } }
                                repeat(100) { launch(Dispatchers.Default) { components.random().snapshot() } }
                            }
                        }
                        RtcTree(TreeConfig(listOf(naming.address))).use { witness ->
                            witness.refresh()
                            val seen = witness.find { it is ComponentNode }.toList().map { it as ComponentNode }
                            assertEquals(40, seen.size)
                            seen.forEach { node ->
                                val snapshot = node.snapshot()
                                assertEquals(LifeCycle.ACTIVE, snapshot.state, snapshot.instanceName)
                                assertEquals(
                                    snapshot.instanceName.removePrefix("relay"),
                                    node.configuration().sets["mine"]?.get("fail"),
                                )
                            }
                        }
                    }
                }
            }
        }
}
