package org.rtcoord.java

import java.util.concurrent.Executor
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.StateChanged
import org.rtcoord.TreeConfig
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.runtime.RuntimeProcess

/**
 * A tool that closes its [JavaTree] leaves no thread behind: its ORB's threads and the tree's own end. The system runs
 * in another process so that every thread started here is the tree's.
 */
class JavaTreeThreadsTest {
    @Test
    fun `closing a tree ends every thread it started`() {
        FixtureProcess.start("--scenario", "localisation").use { system ->
            val before = Thread.getAllStackTraces().keys
            JavaTree(TreeConfig(listOf(system.address))).use { tree ->
                tree.survey("/")
                val gyro = "/${system.address}/${RuntimeProcess.hostContext}/gyro0.rtc"
                tree.subscribe(gyro, StateChanged::class.java, Executor(Runnable::run), {}).use {
                    tree.component(gyro).deactivate()
                }
            }
            // Every thread, the coroutines' too: the tree's dispatchers are its own (kotlinx's shared ones outlived
            // it).
            val deadline = System.nanoTime() + 10_000_000_000
            fun left() = Thread.getAllStackTraces().keys.filter { it !in before && it.isAlive }
            left().forEach { it.join(maxOf(1, (deadline - System.nanoTime()) / 1_000_000)) }
            val left = left().map { it.name }
            assertEquals(emptyList<String>(), left)
        }
    }
}
