package org.rtcoord.idl

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNotEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.omg.CORBA.ORB

/** [ObjectIdentity] agrees with JacORB's `_is_equivalent`, on references made apart. */
class ObjectIdentityTest {
    @Test
    fun `references to one object share an identity, and others do not, as _is_equivalent says`() {
        val orb = ORB.init(emptyArray(), OrbRecipe.properties("127.0.0.1", 0, 1_000))
        try {
            val laser = orb.string_to_object("corbaloc:iiop:127.0.0.1:2809/laser0")
            // Made apart, as two listings make them: through the stringified IOR, another address, a new reference.
            val again = orb.string_to_object(orb.object_to_string(laser))
            val elsewhere = orb.string_to_object("corbaloc:iiop:127.0.0.2:2810/laser0")
            val gyro = orb.string_to_object("corbaloc:iiop:127.0.0.1:2809/gyro0")

            assertTrue(laser._is_equivalent(again))
            assertEquals(ObjectIdentity.of(laser), ObjectIdentity.of(again))
            assertTrue(ObjectIdentity.same(laser, again))
            assertEquals(laser._is_equivalent(elsewhere), ObjectIdentity.same(laser, elsewhere))
            assertFalse(laser._is_equivalent(gyro))
            assertNotEquals(ObjectIdentity.of(laser), ObjectIdentity.of(gyro))
            assertFalse(ObjectIdentity.same(laser, gyro))
        } finally {
            orb.shutdown(true)
            orb.destroy()
        }
    }
}
