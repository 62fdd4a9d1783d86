package org.rtcoord.examples

import java.nio.file.Paths
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.runBlocking
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService
import org.rtcoord.runtime.rtSystem

/**
 * The localisation system with [script] coordinating it, watched as [options] says, plus a second tree to read the
 * result back with. The coordinator's log lines are kept in [log]. With a [pipeline], the system is built as
 * [Pipeline.SEPARATE_PROCESS] says.
 */
class ExampleSystem(
    script: String,
    options: EventOptions,
    args: List<String> = emptyList(),
    pipeline: Pipeline = Pipeline.IN_PROCESS,
) : AutoCloseable {
    /** Where the laser, the odometry and the laser localiser run. */
    enum class Pipeline {
        /** With the gyro, in this JVM's slave manager: the paper's system as `Scenarios.localisation` builds it. */
        IN_PROCESS,

        /**
         * In a slave manager process of their own, joined to the master here, so a test can SIGKILL it; the slave here
         * hosts the gyro and can load every module of the localisation system.
         */
        SEPARATE_PROCESS,
    }

    val naming: NamingService = NamingService.start()
    val system =
        when (pipeline) {
            Pipeline.IN_PROCESS -> Scenarios.localisation(naming.corbaloc)
            Pipeline.SEPARATE_PROCESS ->
                rtSystem(naming.corbaloc) {
                    manager(*Scenarios.localisationModules.toTypedArray())
                    component(Scenarios.gyro)
                    activate("gyro0")
                }
        }
    private val config = TreeConfig(nameServers = listOf(naming.address))
    private val tree = RtcTree(config)
    val witness: RtcTree = RtcTree(config)

    /** The slave manager process hosting the pipeline, with [Pipeline.SEPARATE_PROCESS]. */
    val pipelineProcess: FixtureProcess? = if (pipeline == Pipeline.SEPARATE_PROCESS) startPipeline() else null
    // Copy-on-write: tests iterate it (any, count) while the coordinator appends.
    val log: MutableList<String> = CopyOnWriteArrayList()
    val coordinator: Coordinator =
        Coordinator(tree, runBlocking { scripts.load(Paths.get(script), args, config) }, options) { line ->
            log += line
            println("coordinator: $line")
        }

    private fun startPipeline(): FixtureProcess {
        val process =
            FixtureProcess.start(
                "--naming",
                naming.address,
                "--scenario",
                "components:laser0=laser,odometry0=odometry,laser_localise0=laser_localise",
                "--master",
                system.master!!.runtime.orb.corbaloc("manager"),
            )
        runBlocking {
            witness.connect(path("laser0.rtc:laser"), path("laser_localise0.rtc:laser"))
            witness.connect(path("odometry0.rtc:odo"), path("laser_localise0.rtc:odo"))
            listOf("laser0", "odometry0", "laser_localise0").forEach { witness.component(path("$it.rtc")).activate() }
        }
        return process
    }

    fun path(name: String) = "/${naming.address}/${RuntimeProcess.hostContext}/$name"

    /**
     * OpenRTM's names (`instance.port`) of the ports connected to [port] (`component.rtc:port`), read by the witness.
     */
    suspend fun peers(port: String): Set<String> {
        val own = port.substringBefore(".rtc:") + "." + port.substringAfter(':')
        return witness
            .port(path(port))
            .connections()
            .flatMap { connection -> connection.ports.map { it.fullName } }
            .filter { it != own }
            .toSet()
    }

    override fun close() {
        coordinator.close()
        tree.close()
        witness.close()
        pipelineProcess?.close()
        system.close()
        naming.close()
    }

    companion object {
        /** One host for every test: the compiler warms up once, and scripts are cached under target/. */
        val scripts = ScriptHost(Paths.get("target", "script-cache"))
    }
}
