package org.rtcoord

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNotNull
import org.junit.jupiter.api.Test

/** The tree's own ORB is configured by rtcoord's recipe (OrbRecipe), not by JacORB's files on the class path. */
class OrbConfigurationTest {
    @Test
    fun `a jacorb properties file on the class path does not configure the tree's ORB`() {
        assertNotNull(javaClass.classLoader.getResource("jacorb.properties"), "this module's test file is on the class path")
        RtcTree.create(TreeConfig(listOf("127.0.0.1:1"))).use { tree ->
            val configuration = (tree.core.orb.orb as org.jacorb.orb.ORB).configuration
            assertEquals("unset", configuration.getAttribute("rtcoord.test.from_class_path", "unset"))
            assertEquals("3000", configuration.getAttribute("jacorb.connection.client.pending_reply_timeout"), "the recipe's deadline")
        }
    }
}
