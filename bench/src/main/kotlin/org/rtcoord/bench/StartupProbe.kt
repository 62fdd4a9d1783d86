package org.rtcoord.bench

import kotlinx.coroutines.runBlocking
import org.rtcoord.DirectoryNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import java.lang.management.ManagementFactory
import kotlin.system.exitProcess

/**
 * Run in a fresh JVM on the CLI's class path by the start-up benchmark: times what a browsing command
 * does before it can print, one step at a time, and prints
 * `probe <epoch ms at main> <tree creation ns> <first call ns> <classes loaded>`. The bench times the JVM's
 * own start from its side, up to the epoch milliseconds at main.
 */
internal object StartupProbe {
    @JvmStatic
    fun main(args: Array<String>) {
        val entered = System.currentTimeMillis()
        val address = args.single()
        val start = System.nanoTime()
        val tree = RtcTree.create(TreeConfig(listOf(address)))
        val created = System.nanoTime()
        runBlocking { (tree.node("/$address/") as DirectoryNode).children() }
        val listed = System.nanoTime()
        tree.close()
        println("probe $entered ${created - start} ${listed - created} ${ManagementFactory.getClassLoadingMXBean().totalLoadedClassCount}")
        exitProcess(0)
    }
}
