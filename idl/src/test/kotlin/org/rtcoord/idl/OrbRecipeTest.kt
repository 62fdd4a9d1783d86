package org.rtcoord.idl

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
}
