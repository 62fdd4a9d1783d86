package org.rtcoord.examples

import kotlinx.coroutines.runBlocking
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.fixtures.FixtureRuntime
import org.rtcoord.fixtures.Scenarios
import org.rtcoord.fixtures.naming.NamingService
import java.nio.file.Paths
import java.util.concurrent.CopyOnWriteArrayList

/**
 * The localisation system with [script] coordinating it, watched as [options] says, plus a second
 * tree to read the result back with. The coordinator's log lines are kept in [log].
 */
class ExampleSystem(script: String, options: EventOptions, args: List<String> = emptyList()) : AutoCloseable {
    val naming: NamingService = NamingService.start()
    val system = Scenarios.localisation(naming.corbaloc)
    private val config = TreeConfig(nameServers = listOf(naming.address))
    private val tree = RtcTree.create(config)
    val witness: RtcTree = RtcTree.create(config)
    val log: MutableList<String> = CopyOnWriteArrayList()
    val coordinator: Coordinator = Coordinator(tree, runBlocking { scripts.load(Paths.get(script), args, config) }, options) { line ->
        log += line
        println("coordinator: $line")
    }

    fun path(name: String) = "/${naming.address}/${FixtureRuntime.hostContext}/$name"

    override fun close() {
        coordinator.close()
        tree.close()
        witness.close()
        system.close()
        naming.close()
    }

    companion object {
        /** One host for every test: the compiler warms up once, and scripts are cached under target/. */
        val scripts = ScriptHost(Paths.get("target", "script-cache"))
    }
}
