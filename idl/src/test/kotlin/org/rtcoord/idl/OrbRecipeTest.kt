package org.rtcoord.idl

import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import java.util.concurrent.locks.LockSupport
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CORBA.ORB
import org.omg.PortableServer.POAHelper

/** What [OrbRecipe] configures, checked on the ORBs it makes. */
class OrbRecipeTest {
    private fun orb() = ORB.init(emptyArray(), OrbRecipe.properties("127.0.0.1", 0, 1_000)) as org.jacorb.orb.ORB

    @Test
    fun `an ORB's buffers stay pooled when another ORB of the JVM is destroyed`() {
        val ending = orb()
        val staying = orb()
        try {
            val buffer = ByteArray(1023)
            staying.bufferManager.returnBuffer(buffer, true)
            ending.shutdown(true)
            ending.destroy()
            // JacORB's shared pool would have been emptied, without its lock, under the ORB that stays.
            assertTrue(buffer === staying.bufferManager.getBuffer(1023), "the staying ORB's pooled buffer was dropped")
        } finally {
            staying.shutdown(true)
            staying.destroy()
        }
    }

    @Test
    fun `an ORB keeps as many request threads idle as it is told, and starts more up to the same limit`() {
        val few = OrbRecipe.properties("127.0.0.1", 0, 1_000, 8)
        val all = OrbRecipe.properties("127.0.0.1", 0, 1_000)
        assertEquals("8", few.getProperty("jacorb.poa.thread_pool_min"))
        assertEquals(all.getProperty("jacorb.poa.thread_pool_max"), few.getProperty("jacorb.poa.thread_pool_max"))
        assertEquals(all.getProperty("jacorb.poa.thread_pool_max"), all.getProperty("jacorb.poa.thread_pool_min"))
        val refused =
            assertThrows(IllegalArgumentException::class.java) {
                OrbRecipe.properties("127.0.0.1", 0, 1_000, OrbRecipe.REQUEST_THREADS + 1)
            }
        assertEquals("idleRequestThreads must be 1 to 64, was 65", refused.message)
    }

    @Test
    fun `the reader threads of closed connections end, but one`() {
        val server = orb()
        val clients = List(4) { orb() }
        try {
            val poa = POAHelper.narrow(server.resolve_initial_references("RootPOA"))
            poa.the_POAManager().activate()
            val received = CountDownLatch(clients.size)
            val observer =
                object : OpenRTM.ComponentObserverPOA() {
                    override fun update_status(kind: OpenRTM.StatusKind, hint: String?) = received.countDown()
                }
            val ior = server.object_to_string(poa.servant_to_reference(observer))
            // A oneway call from each client: its connection stays open, and the server has a reader for it.
            for (client in clients) OpenRTM.ComponentObserverHelper.unchecked_narrow(client.string_to_object(ior))
                .update_status(OpenRTM.StatusKind.HEARTBEAT, "")
            assertTrue(received.await(10, TimeUnit.SECONDS), "the observer heard ${clients.size - received.count}")
            assertTrue(serverReaders() >= clients.size, "${serverReaders()} readers for ${clients.size} connections")

            clients.forEach {
                it.shutdown(true)
                it.destroy()
            }
            val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10)
            // Parked between looks, not spinning: the readers that are to end need the cores.
            while (serverReaders() > 1 && System.nanoTime() < deadline) LockSupport.parkNanos(LOOK_NANOS)
            assertEquals(1, serverReaders(), "readers left once every connection closed")
        } finally {
            server.shutdown(true)
            server.destroy()
        }
    }

    /** The live threads that read a server connection, busy or idle in JacORB's pool. */
    private fun serverReaders() =
        Thread.getAllStackTraces().keys.count { it.isAlive && it.name.startsWith("ServerMessageReceptor") }

    private companion object {
        val LOOK_NANOS = TimeUnit.MILLISECONDS.toNanos(10)
    }
}
