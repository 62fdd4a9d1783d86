package org.rtcoord.internal

import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CORBA.ORB
import org.omg.PortableServer.POAHelper
import org.rtcoord.idl.OrbRecipe

/** [RandomIdPoa] serving observers to another ORB over loopback IIOP, as a tree serves them to components. */
class RandomIdPoaTest {
    private class Recorder(expected: Int) : OpenRTM.ComponentObserverPOA() {
        val hints = CopyOnWriteArrayList<String>()
        val threads = CopyOnWriteArrayList<String>()
        val received = CountDownLatch(expected)

        override fun update_status(kind: OpenRTM.StatusKind, hint: String) {
            hints += hint
            threads += Thread.currentThread().name
            received.countDown()
        }
    }

    private fun rootPoa(orb: ORB) = POAHelper.narrow(orb.resolve_initial_references("RootPOA"))

    private fun remote(reference: org.omg.CORBA.Object): OpenRTM.ComponentObserver =
        OpenRTM.ComponentObserverHelper.narrow(client.string_to_object(server.object_to_string(reference)))

    @Test
    fun `a served object answers over IIOP until it is closed, then it does not exist, and its ORB still shuts down`() {
        val own = ORB.init(emptyArray(), OrbRecipe.properties("127.0.0.1", 0, 5_000))
        val served = RandomIdPoa({ rootPoa(own) }, "answers", singleThread = true).serve(Recorder(1))
        val observer =
            OpenRTM.ComponentObserverHelper.narrow(client.string_to_object(own.object_to_string(served.reference)))
        assertFalse(observer._non_existent(), "served")

        served.close()
        assertTrue(observer._non_existent(), "closed")

        val shutdown = Thread { own.shutdown(true) }.apply { start() }
        shutdown.join(10_000)
        assertFalse(shutdown.isAlive, "the ORB shut down: no call left unfinished in its POA")
        own.destroy()
    }

    @Test
    fun `one thread takes a single-threaded POA's calls in the order they were sent`() {
        val recorder = Recorder(HINTS)
        val observer =
            remote(RandomIdPoa({ rootPoa(server) }, "ordered", singleThread = true).serve(recorder).reference)

        repeat(HINTS) { observer.update_status(OpenRTM.StatusKind.COMPONENT_PROFILE, "$it") }

        assertTrue(recorder.received.await(10, TimeUnit.SECONDS), "received ${recorder.hints.size} of $HINTS")
        assertEquals((0 until HINTS).map { "$it" }, recorder.hints)
        assertEquals(1, recorder.threads.toSet().size, "threads: ${recorder.threads.toSet()}")
    }

    @Test
    fun `objects get ids of their own, and the POA starts no thread to forget them`() {
        rootPoa(server)
        val before = removalThreads()
        val poa = RandomIdPoa({ rootPoa(server) }, "ids", singleThread = true)
        val served = List(3) { poa.serve(Recorder(0)) }
        served.forEach { assertFalse(remote(it.reference)._non_existent()) }
        served.forEach { it.close() }

        assertEquals(3, served.map { server.object_to_string(it.reference) }.toSet().size, "three references")
        assertEquals(before, removalThreads(), "JacORB's threads that take objects out of a POA's map")
    }

    private fun removalThreads(): Set<String> =
        Thread.getAllStackTraces().keys.map { it.name }.filter { it.startsWith("AOMRemoval") }.toSet()

    companion object {
        private const val HINTS = 200
        private val server: ORB = ORB.init(emptyArray(), OrbRecipe.properties("127.0.0.1", 0, 5_000))
        private val client: ORB = ORB.init(emptyArray(), OrbRecipe.properties("127.0.0.1", 0, 5_000))

        @JvmStatic
        @AfterAll
        fun shutdown() {
            client.destroy()
            server.shutdown(true)
            server.destroy()
        }
    }
}
