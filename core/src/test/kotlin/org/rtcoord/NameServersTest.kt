package org.rtcoord

import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.Socket
import kotlin.time.Duration.Companion.seconds
import kotlin.time.measureTime
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.rtcoord.fixtures.OmniNames
import org.rtcoord.runtime.RuntimeManager
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

class NameServersTest {
    @Test
    fun `several name servers at once, one of them unreachable, each complete`(): Unit = runBlocking {
        refusedPort().use { refused ->
            val nowhere = "127.0.0.1:${refused.localPort}"
            OmniNames.start().use { omni ->
                NamingService.start().use { embedded ->
                    Scenarios.scale(omni.corbaloc, 5).use {
                        Scenarios.localisation(embedded.corbaloc).use {
                            RtcTree(TreeConfig(listOf(omni.address, nowhere, embedded.address))).use { tree ->
                                val elapsed = measureTime { tree.refresh() }
                                assertTrue(elapsed < 3.seconds, "refresh took $elapsed")

                                val servers = tree.root.children()
                                assertEquals(
                                    listOf(NodeKind.NAME_SERVER, NodeKind.ZOMBIE, NodeKind.NAME_SERVER),
                                    servers.map { it.kind },
                                )
                                assertTrue((servers[1] as ZombieNode).cause is UnreachableException)
                                val components = tree.find { it is ComponentNode }.toList()
                                assertEquals(5, components.count { it.path.nameServer == omni.address })
                                assertEquals(
                                    4,
                                    components.count { it.path.nameServer == embedded.address },
                                    "4 in naming, each once: the manager lists aliases",
                                )
                            }
                        }
                    }
                }
            }
        }
    }

    @Test
    fun `name servers are added and removed at run time`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            RtcTree().use { tree ->
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
    fun `a name server written two ways is one node, named as first given, reached by either`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            Scenarios.localisation(naming.corbaloc).use {
                RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                    val other = "localhost:${naming.port}"
                    val server = tree.nameServers.single()
                    assertTrue(server === tree.addNameServer(other))
                    assertTrue(server === tree.addNameServer("corbaloc:iiop:$other/NameService"))
                    val gyro = tree.component("/$other/${RuntimeProcess.hostContext}/gyro0.rtc")
                    assertEquals("/${naming.address}/${RuntimeProcess.hostContext}/gyro0.rtc", gyro.path.toString())
                    assertEquals(listOf(server), tree.nameServers)
                    assertEquals(1, tree.find { it is ComponentNode && it.name == "gyro0.rtc" }.toList().size)
                    assertTrue(tree.removeNameServer(other))
                    assertEquals(emptyList<NameServerNode>(), tree.nameServers)
                }
            }
        }
    }

    @Test
    fun `a name server restarted empty is read again, and components that register again are found`(): Unit =
        runBlocking {
            var naming = NamingService.start()
            try {
                Scenarios.localisation(naming.corbaloc).use { system ->
                    RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                        tree.refresh()
                        assertEquals(
                            4,
                            tree.find { it is ComponentNode }.toList().size,
                            "each once, at its naming path",
                        )

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

    @Test
    fun `an address where a manager answers is a node saying so, not an unreachable name server`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            RuntimeProcess.start(null).use { runtime ->
                RuntimeManager(runtime, isMaster = true)
                val managerPort = "${runtime.orb.host}:${runtime.orb.port}"
                RtcTree(TreeConfig(listOf(managerPort, naming.address))).use { tree ->
                    tree.refresh()
                    val servers = tree.root.children()
                    assertEquals(listOf(NodeKind.ZOMBIE, NodeKind.NAME_SERVER), servers.map { it.kind })
                    val cause = (servers[0] as ZombieNode).cause
                    assertEquals("/$managerPort: is a manager (IDL:RTM/Manager:1.0), not a name server", cause.message)
                    val listing =
                        assertThrows<WrongKindException> { (tree.node("/$managerPort") as DirectoryNode).children() }
                    assertEquals(cause.message, listing.message)
                }
            }
        }
    }

    @Test
    fun `a manager answering at the key NameService is a node saying so`(): Unit = runBlocking {
        RuntimeProcess.start(null).use { runtime ->
            val manager = RuntimeManager(runtime, isMaster = true)
            runtime.orb.bindKey("NameService", manager.ref)
            val address = "${runtime.orb.host}:${runtime.orb.port}"
            RtcTree(TreeConfig(listOf(address))).use { tree ->
                tree.root.survey()
                val server = tree.root.children().single() as ZombieNode
                assertEquals("/$address: is a manager (IDL:RTM/Manager:1.0), not a name server", server.cause.message)
            }
        }
    }

    /**
     * A socket bound to a port of its own and never listening: connections to it are refused, and no server can take
     * the port while it is held.
     */
    private fun refusedPort(): Socket = Socket().apply { bind(InetSocketAddress(InetAddress.getLoopbackAddress(), 0)) }
}
