@file:JvmName("MultiHostCoordinator")

package org.rtcoord

import kotlin.system.exitProcess
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withContext

/**
 * The coordinator of [MultiHostTest], on a host of its own: watches everything on the name server named by its argument
 * (`host:port`) and prints `event TYPE PATH [OLD NEW]` per event, `ready` once it watches. A `list` line on stdin
 * prints the tree as it knows it now, without reading anything: one `component PATH STATE` or `zombie PATH` line per
 * node, then `listed`.
 */
fun main(args: Array<String>) {
    runBlocking {
        // Short deadlines and heartbeats keep the test short: a cut host is presumed dead within about 4 s.
        // Tighter limits (1 s) raised false alarms for the host that stays connected on a loaded 2-core machine.
        RtcTree(TreeConfig(listOf(args[0]), callTimeout = 2.seconds)).use { tree ->
            tree.on("/${args[0]}", RtcEvent::class.java, EventOptions(heartbeat = 500.milliseconds, missedBeats = 4)) {
                event ->
                val change = (event as? StateChanged)?.let { " ${it.old} ${it.new}" }.orEmpty()
                println("event ${event.javaClass.simpleName} ${event.path}$change")
            }
            println("ready")
            val input = System.`in`.bufferedReader()
            while (true) {
                val line = withContext(Dispatchers.IO) { input.readLine() } ?: break
                if (line == "list") list(tree.root)
            }
        }
    }
    exitProcess(0)
}

private fun list(node: Node) {
    when (node) {
        is ComponentNode -> println("component ${node.path} ${node.snapshots.value?.state}")
        is ZombieNode -> println("zombie ${node.path}")
        is DirectoryNode -> node.listed.value?.forEach(::list)
        else -> Unit
    }
    if (node is RootNode) println("listed")
}
