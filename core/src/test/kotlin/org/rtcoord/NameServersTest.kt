package org.rtcoord

import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.OmniNames
import org.rtcoord.fixtures.Scenarios
import org.rtcoord.fixtures.naming.NamingService
import java.net.InetAddress
import java.net.ServerSocket
import kotlin.time.Duration.Companion.seconds
import kotlin.time.measureTime

class NameServersTest {
    @Test
    fun `several name servers at once, one of them unreachable, each complete`(): Unit = runBlocking {
        val nowhere = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { "127.0.0.1:${it.localPort}" }
        OmniNames.start().use { omni ->
            NamingService.start().use { embedded ->
                Scenarios.scale(omni.corbaloc, 5).use {
                    Scenarios.localisation(embedded.corbaloc).use {
                        RtcTree.create(TreeConfig(listOf(omni.address, nowhere, embedded.address))).use { tree ->
                            val elapsed = measureTime { tree.refresh() }
                            assertTrue(elapsed < 3.seconds, "refresh took $elapsed")

                            val servers = tree.root.children()
                            assertEquals(listOf(NodeKind.NAME_SERVER, NodeKind.ZOMBIE, NodeKind.NAME_SERVER), servers.map { it.kind })
                            assertTrue((servers[1] as ZombieNode).cause is UnreachableException)
                            val components = tree.find { it is ComponentNode }.toList()
                            assertEquals(5, components.count { it.path.nameServer == omni.address })
                            assertEquals(8, components.count { it.path.nameServer == embedded.address }, "4 in naming, 4 below the manager")
                        }
                    }
                }
            }
        }
    }

    @Test
    fun `name servers are added and removed at run time`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            RtcTree.create().use { tree ->
                assertTrue(tree.root.children().isEmpty())
                val server = tree.addNameServer("corbaloc:iiop:${naming.address}/NameService")
                assertTrue(server === tree.addNameServer(naming.address))
                assertEquals(listOf(server), tree.root.children().also { tree.root.refresh() })
                assertTrue(tree.removeNameServer(naming.address))
                tree.root.refresh()
                assertFalse(tree.root.children().contains(server))
            }
        }
    }

    @Test
    fun `a name server restarted empty is read again, and components that register again are found`(): Unit = runBlocking {
        var naming = NamingService.start()
        try {
            Scenarios.localisation(naming.corbaloc).use { system ->
                RtcTree.create(TreeConfig(listOf(naming.address))).use { tree ->
                    tree.refresh()
                    assertEquals(8, tree.find { it is ComponentNode }.toList().size)

                    val port = naming.port
                    naming.close()
                    naming = NamingService.start(port)
                    tree.refresh()
                    assertEquals(emptyList<Node>(), tree.find { it is ComponentNode }.toList())

                    system.runtime.rebindAll()
                    tree.refresh()
                    val found = tree.find { it is ComponentNode }.toList().map { it.name }.toSet()
                    assertEquals(setOf("laser0.rtc", "gyro0.rtc", "odometry0.rtc", "laser_localise0.rtc"), found)
                    assertEquals(LifeCycle.ACTIVE, tree.componentNamed("laser0").state())
                }
            }
        } finally {
            naming.close()
        }
    }
}
