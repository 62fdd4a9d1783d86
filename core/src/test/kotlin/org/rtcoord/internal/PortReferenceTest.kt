package org.rtcoord.internal

import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test
import org.rtcoord.ComponentNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * A component's port references are not kept with it (JacORB's weigh about a kilobyte each): a port operation takes
 * them from the component's last read while that is at hand, else reads the profile for them.
 */
class PortReferenceTest {
    @Test
    fun `a port's reference is read when no read of the component is at hand`(): Unit = runBlocking {
        NamingService.start().use { naming ->
            Scenarios.scale(naming.corbaloc, 2).use {
                RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                    // Listed, not read: nothing holds the components' ports.
                    val components = tree.find { it is ComponentNode }.toList().map { (it as ComponentNode).component }
                    assertEquals(2, components.size)
                    for (component in components) {
                        val name = component.instanceName("test")
                        val out = component.port(name, "out")
                        assertEquals("$name.out", out?.get_port_profile()?.name, "read from the profile")
                        assertNull(component.port(name, "nonexistent"), "a port the component lacks")
                    }
                }
            }
        }
    }
}
