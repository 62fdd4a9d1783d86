package org.rtcoord.cli

import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig

/** Progress during a long discovery, as a terminal would get it; a quick one shows nothing. */
class DiscoveryProgressTest {
    private val localisation = Localisation()
    private val tree = RtcTree(TreeConfig(listOf(localisation.naming.address), callTimeout = 1500.milliseconds))
    private val written = mutableListOf<String>()
    private val progress = StatusLine { written += it }

    @AfterEach
    fun stop() {
        tree.close()
        localisation.close()
    }

    @Test
    fun `a slow discovery rewrites one status line, then erases it`() {
        val gyro = localisation.system.component("gyro0")
        gyro.hang()
        try {
            runBlocking { discover(tree.node(localisation.host), progress) }
        } finally {
            gyro.release()
        }
        assertTrue(written.size >= 2, written.toString())
        assertTrue(
            written.dropLast(1).all {
                Regex("""\rrtcoord: discovering: \d+ components in \d+ directories so far\u001b\[K""").matches(it)
            },
            written.toString(),
        )
        assertEquals("\r\u001b[K", written.last())
    }

    @Test
    fun `a quick discovery shows nothing`() {
        runBlocking { discover(tree.node(localisation.host), progress) }
        assertEquals(emptyList<String>(), written)
    }
}
