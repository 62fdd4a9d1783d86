package org.rtcoord.bench

import java.lang.management.ManagementFactory
import kotlin.system.exitProcess
import kotlinx.coroutines.runBlocking
import org.rtcoord.DirectoryNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.cli.rtcoord
import org.rtcoord.cli.useCommandLogging

/**
 * Run in a fresh JVM on the CLI's class path by the start-up benchmark: does what `rtcoord ls -l -R` does before it
 * prints, one step at a time, and prints `probe <epoch ms at main> <command line ns>
 * <tree creation ns> <first call ns> <rest of the listing ns> <close ns> <epoch ms at the end>`. The bench times the
 * JVM's own start and exit from its side, up to and from those epoch times. With a second argument, `classes`, it also
 * prints how many classes were loaded: JMX, which counts them, takes longer to start than some of the steps it would
 * count.
 */
internal object StartupProbe {
    @JvmStatic
    fun main(args: Array<String>) {
        val entered = System.currentTimeMillis()
        val address = args.first()
        val start = System.nanoTime()
        useCommandLogging()
        rtcoord(listOf("ls", "-l", "-R", "/$address/"))
        val parsed = System.nanoTime()
        val tree = RtcTree(TreeConfig(listOf(address)))
        val created = System.nanoTime()
        val server = runBlocking { tree.node("/$address/") as DirectoryNode }
        runBlocking { server.children() }
        val listed = System.nanoTime()
        runBlocking { server.survey() }
        val surveyed = System.nanoTime()
        tree.close()
        val closed = System.nanoTime()
        println(
            "probe $entered ${parsed - start} ${created - parsed} ${listed - created} ${surveyed - listed} ${closed - surveyed} ${System.currentTimeMillis()}"
        )
        if (args.getOrNull(1) == "classes")
            println("classes ${ManagementFactory.getClassLoadingMXBean().totalLoadedClassCount}")
        exitProcess(0)
    }
}
