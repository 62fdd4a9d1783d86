package org.rtcoord.internal

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test

class ManagerNamingTest {
    @Test
    fun `C++ slaves, which all carry their master's name, are told apart by their instance names`() {
        // rtls names both `manager`; OpenRtmCppTest's supervision failed on real rtcd2 when rtcoord did too.
        val byHand = mapOf("name" to "manager", "instance_name" to "pipeline", "is_master" to "NO")
        val startedByTheMaster = mapOf("name" to "manager", "instance_name" to "manager_4242", "is_master" to "NO")
        assertEquals(listOf("pipeline", "manager_4242"), listOf(byHand, startedByTheMaster).map(ManagerCalls::nameOf))
    }

    @Test
    fun `a profile without an instance name falls back on the name, then on manager`() {
        assertEquals("manager", ManagerCalls.nameOf(mapOf("name" to "manager", "instance_name" to "")))
        assertEquals("manager", ManagerCalls.nameOf(emptyMap()))
    }
}
