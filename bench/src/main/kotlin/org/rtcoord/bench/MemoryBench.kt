package org.rtcoord.bench

import java.lang.ref.Reference
import kotlin.time.Duration.Companion.minutes
import kotlinx.coroutines.flow.toList
import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.fixtures.FixtureProcess

/**
 * Heap per component node: the live heap a tree holds once it has read a system of N components (full snapshots:
 * profiles, ports, contexts, states), less what it held with only the name server listed, divided by N. The system is
 * served by a fixture JVM of its own; the largest size the machine can serve, of those tried, is the one reported.
 */
internal class MemoryBench(private val options: BenchOptions, private val report: Report) {
    suspend fun run() {
        val problems = mutableListOf<String>()
        for (n in options.memorySizes) {
            val fixtures =
                try {
                    FixtureProcess.start("--scenario", "scale:$n", timeout = 15.minutes)
                } catch (e: Exception) {
                    problems += "N=$n: ${e.message}"
                    continue
                }
            fixtures.use {
                val tried = if (problems.isEmpty()) "" else "; larger sizes failed: ${problems.joinToString()}"
                report.section(
                    "memory: heap per component node, tree of N=$n components (fixtures in a separate JVM$tried)"
                )
                val perNode = List(options.memoryRepetitions) { measure(n, fixtures.address) }
                report.row(
                    "live heap per component",
                    Samples(perNode.map { it.first }, "bytes"),
                    perNode.first().second,
                )
            }
            return
        }
        report.section("memory: heap per component node")
        report.skipped("live heap per component", "no fixture system could start: ${problems.joinToString()}")
    }

    /** Bytes per component, and what they cover. */
    private suspend fun measure(n: Int, address: String): Pair<Double, String> {
        // A generous deadline: on a loaded machine a component answering late must not turn into a zombie.
        val tree = RtcTree(TreeConfig(listOf(address), callTimeout = 1.minutes))
        try {
            tree.node("/$address/")
            val before = Heap.live()
            tree.refresh()
            val after = Heap.live()
            val nodes = tree.find().toList()
            val components = nodes.count { it is ComponentNode }
            check(components == n) { "the tree holds $components components, not $n" }
            val directories = nodes.count { it is DirectoryNode }
            Reference.reachabilityFence(tree)
            return (after - before).toDouble() / n to
                "${figure((after - before) / Heap.MB)} MB for $n components and $directories directories, counted with the components"
        } finally {
            tree.close()
        }
    }
}
