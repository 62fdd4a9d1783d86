package org.rtcoord.idl

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CORBA.ORB

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
}
