package org.rtcoord

import java.net.Inet4Address
import java.net.NetworkInterface
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assumptions.assumeTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.iiopAddresses
import org.rtcoord.fixtures.listeningSockets
import org.rtcoord.internal.ListenAddress

/**
 * The tree's ORB listens on one address and hands out references carrying only that one: by default the address that
 * reaches its first name server (loopback for a local one), or the one configured.
 */
class ListenAddressTest {
    /** The addresses in the reference of the observer [tree] attached to laser0, and where its ORB listens. */
    private fun observed(localisation: LocalisationSystem, tree: RtcTree): Pair<List<String>, List<String>> =
        runBlocking {
            tree.on(localisation.path("laser0.rtc"), RtcEvent::class.java, EventOptions(WatchMode.PUSH)) {}
            val laser = localisation.system.component("laser0")
            val observer = laser.observerReferences.single()
            val carried = iiopAddresses(localisation.system.runtime.orb.orb, observer)
            val port = carried.first().substringAfterLast(':').toInt()
            carried to listeningSockets().filter { it.port == port }.map { "${it.address.hostAddress}:${it.port}" }
        }

    @Test
    fun `with a name server on this host the tree listens on loopback alone`() {
        LocalisationSystem().use { localisation ->
            val (carried, listening) = observed(localisation, localisation.tree)
            assertEquals(1, carried.size, "one address in the observer's reference: $carried")
            assertEquals("127.0.0.1", carried.single().substringBeforeLast(':'))
            assertEquals(carried, listening, "the listening socket is the advertised one, not a wildcard")
        }
    }

    @Test
    fun `a configured address is the only one listened on and handed out`() {
        LocalisationSystem().use { localisation ->
            RtcTree(TreeConfig(listOf(localisation.naming.address), listenAddress = "127.0.0.2")).use { tree ->
                val (carried, listening) = observed(localisation, tree)
                assertEquals(listOf("127.0.0.2"), carried.map { it.substringBeforeLast(':') })
                assertEquals(carried, listening)
            }
        }
    }

    @Test
    fun `a tree that only reads the system never listens, and closes`() {
        LocalisationSystem().use { localisation ->
            fun listening() = listeningSockets().filter { it.address.hostAddress == READER_ADDRESS }
            RtcTree(TreeConfig(listOf(localisation.naming.address), listenAddress = READER_ADDRESS)).use { tree ->
                runBlocking {
                    val laser = tree.component(localisation.path("laser0.rtc"))
                    assertEquals(LifeCycle.ACTIVE, laser.state())
                    assertEquals(listOf("laser"), laser.snapshot().ports.map { it.name })
                }
                assertEquals(emptyList<Any>(), listening(), "no object served, so no root POA and no listening socket")
            }
            assertEquals(emptyList<Any>(), listening(), "closing made none either")
        }
    }

    @Test
    fun `an address that is not this host's is refused when the tree is configured`() {
        val foreign = assertThrows(IllegalArgumentException::class.java) { TreeConfig(listenAddress = "203.0.113.7") }
        assertEquals("listen address: 203.0.113.7 is not an address of this host", foreign.message)
        val unknown =
            assertThrows(IllegalArgumentException::class.java) { TreeConfig(listenAddress = "no-such-host.invalid") }
        assertEquals("listen address: cannot resolve 'no-such-host.invalid'", unknown.message)
    }

    @Test
    fun `the default is the source address of the route to the name server`() {
        assertEquals("127.0.0.1", ListenAddress.toward(null))
        assertEquals("127.0.0.1", ListenAddress.toward("localhost"))
        assertEquals(
            "127.0.0.1",
            ListenAddress.toward("127.0.0.5"),
            "any loopback name server is reached from loopback",
        )
        assertEquals("127.0.0.1", ListenAddress.toward("no-such-host.invalid"))
        // A name server on one of this host's own non-loopback addresses is reached from that address.
        val own =
            NetworkInterface.networkInterfaces()
                .toList()
                .filter { it.isUp && !it.isLoopback }
                .flatMap { it.inetAddresses.toList() }
                .firstOrNull { it is Inet4Address }
        assumeTrue(own != null, "this host has no IPv4 address but loopback")
        assertEquals(own!!.hostAddress, ListenAddress.toward(own.hostAddress))
    }

    private companion object {
        /** An address of this host that no other test listens on. */
        const val READER_ADDRESS = "127.0.0.3"
    }
}
