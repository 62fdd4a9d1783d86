package org.rtcoord.examples

import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assumptions.assumeTrue
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.fixtures.OmniNames
import org.rtcoord.fixtures.awaitValue
import java.net.InetAddress
import java.net.ServerSocket
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.seconds

/**
 * The paper's localisation system on a real OpenRTM-aist-Python installation: omniNames, a master
 * manager and a slave manager (both `rtcd_python`), the slave hosting `laser0`, `gyro0`, `odometry0`
 * and `laser_localise0` from the modules in `examples/openrtm-python`, with `odo_localise.py` loadable
 * but not loaded. Connected and activated as the fixtures' localisation system is. The master's
 * `manager_cmd` starts another slave when it has none that can create a component, as `rtcd2_python`
 * would.
 *
 * [python] runs OpenRTM-aist-Python: the interpreter named by `RTCOORD_OPENRTM_PYTHON`, which must
 * import `OpenRTM_aist`. The test is skipped without it (no package registry we reach has OpenRTM-aist).
 */
class OpenRtmPythonSystem private constructor(private val python: String) : AutoCloseable {
    private val directory: Path = Files.createTempDirectory("rtcoord-openrtm")
    private val omniNames = OmniNames.start()
    private val masterPort = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { it.localPort }
    private val managers = mutableListOf<Process>()
    val witness: RtcTree = RtcTree.create(TreeConfig(nameServers = listOf(omniNames.address)))

    /** The naming service's address (`host:port`), for the coordinator's tree. */
    val naming: String get() = omniNames.address

    /** The naming context the components bind in: OpenRTM's `%h.host_cxt` for this host. */
    lateinit var context: String
        private set

    /** The path of [name] (`laser0.rtc`, `laser0.rtc:laser`) in the components' context. */
    fun path(name: String): String = "$context/$name"

    private fun start() {
        val rtcd = directory.resolve("rtcd")
        Files.write(rtcd, listOf("#!/bin/sh", "exec '$python' -c '$RTCD' \"$@\""))
        rtcd.toFile().setExecutable(true)
        managers += manager(
            "master",
            directory,
            "manager.is_master: YES",
            "manager.instance_name: manager",
            "manager.modules.load_path: ${components.toAbsolutePath()}",
            "manager.modules.Python.manager_cmd: $rtcd",
        )
        // A slave joins the master it finds when it starts: the master must be up by then.
        runBlocking {
            awaitValue("the master manager in naming", 30.seconds) {
                runBlocking { runCatching { witness.refresh(); witness.find().toList().firstOrNull { it.name == "manager.mgr" } }.getOrNull() }
            }
        }
        managers += manager(
            "slave",
            components,
            "manager.is_master: NO",
            "manager.modules.load_path: ${components.toAbsolutePath()}",
            "manager.modules.preload: laser.py, gyro.py, odometry.py, laser_localise.py",
            "manager.components.precreate: laser, gyro, odometry, laser_localise",
            "exec_cxt.periodic.rate: 20",
        )
        runBlocking {
            val laser = awaitValue("the slave's components in naming", 30.seconds) {
                runBlocking { runCatching { witness.refresh(); witness.componentNamed("laser_localise0.rtc"); witness.componentNamed("laser0.rtc") }.getOrNull() }
            }
            context = laser.path.parent.toString()
            witness.connect(path("laser0.rtc:laser"), path("laser_localise0.rtc:laser"))
            witness.connect(path("odometry0.rtc:odo"), path("laser_localise0.rtc:odo"))
            listOf("laser0", "gyro0", "odometry0", "laser_localise0").forEach { witness.component(path("$it.rtc")).activate() }
        }
    }

    /** Starts `rtcd_python` as the manager [role] in [workingDirectory], with these `rtc.conf` lines after the shared ones. */
    private fun manager(role: String, workingDirectory: Path, vararg lines: String): Process {
        val conf = directory.resolve("$role.conf")
        val shared = listOf(
            "corba.nameservers: ${omniNames.address}",
            "corba.endpoints: 127.0.0.1",
            "corba.master_manager: 127.0.0.1:$masterPort",
            "manager.naming_formats: %h.host_cxt/%n.mgr",
            "naming.formats: %h.host_cxt/%n.rtc",
            "logger.enable: YES",
            "logger.log_level: WARN",
            "logger.file_name: ${directory.resolve("$role.log")}",
        )
        Files.write(conf, shared + lines)
        return ProcessBuilder(python, "-c", RTCD, "-f", conf.toString())
            .directory(workingDirectory.toFile())
            .redirectErrorStream(true)
            .redirectOutput(directory.resolve("$role.out").toFile())
            .start()
    }

    /** The installed `OpenRTM_aist` package's directory, which holds its examples and extension modules. */
    private val installation: Path by lazy {
        Paths.get(ProcessBuilder(python, "-c", "import os, OpenRTM_aist; print(os.path.dirname(OpenRTM_aist.__file__))").start().inputStream.bufferedReader().readText().trim())
    }

    /**
     * Starts OpenRTM-aist's own ConfigSample (with its `configsample.conf`: sets `mode0` and `mode1` hold
     * values outside its `__constraints__`) and SeqIO's `SequenceOutComponent` (its `on_execute` sleeps
     * 1 s) from the installation's examples, inactive, in a manager of their own that is no slave of the
     * master; returns once both are in naming.
     */
    fun startOpenRtmExamples() {
        val examples = installation.resolve("examples")
        standalone(
            "examples",
            listOf(examples.resolve("ConfigSample"), examples.resolve("SeqIO")),
            listOf("ConfigSample", "SeqOut"),
            listOf("ConfigSample", "SeqOut"),
            listOf("ConfigSample0", "SequenceOutComponent0"),
            "example.ConfigSample.config_file: ${examples.resolve("ConfigSample/configsample.conf")}",
        )
    }

    /**
     * Starts OpenRTM-aist's StaticFsm `Microwave` from the installation's examples and `fsm_buttons` (from
     * `examples/openrtm-python`, the example's Inputbutton pressed through configuration), inactive and
     * unconnected, in a manager of their own that loads the FSM4RTC observer (`ext/fsm4rtc_observer`)
     * beside the OpenRTM one every Python manager has, and the `ExtendedFsmService` provider
     * (`ext/extended_fsm`); returns once both are in naming.
     */
    fun startMicrowave() {
        val ext = installation.resolve("ext")
        standalone(
            "fsm",
            listOf(ext.resolve("fsm4rtc_observer"), ext.resolve("extended_fsm"), installation.resolve("examples/StaticFsm"), components.toAbsolutePath()),
            listOf("ComponentObserverConsumer", "ExtendedFsmServiceProvider", "Microwave", "fsm_buttons"),
            listOf("Microwave", "fsm_buttons"),
            listOf("Microwave0", "fsm_buttons0"),
        )
    }

    /**
     * Starts the manager [role], loading [modules] (`.py` files) from [loadPath] and creating [precreate], as
     * a manager of its own: it knows a master nobody listens at, so the test's master never hands it a
     * creation. Returns once [instances] are in naming.
     */
    private fun standalone(role: String, loadPath: List<Path>, modules: List<String>, precreate: List<String>, instances: List<String>, vararg lines: String) {
        val loose = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { it.localPort }
        managers += manager(
            role,
            directory,
            "corba.master_manager: 127.0.0.1:$loose",
            "manager.is_master: NO",
            "manager.modules.load_path: ${loadPath.joinToString()}",
            "manager.modules.preload: ${modules.joinToString { "$it.py" }}",
            "manager.components.precreate: ${precreate.joinToString()}",
            *lines,
        )
        runBlocking {
            awaitValue("${instances.joinToString(" and ")} in naming", 30.seconds) {
                runBlocking { runCatching { witness.refresh(); instances.forEach { witness.componentNamed("$it.rtc") } }.getOrNull() }
            }
        }
    }

    /** What the manager [role] (`fsm`, `examples`, ...) and its components printed so far. */
    fun output(role: String): String = Files.readString(directory.resolve("$role.out"))

    /** Kills the slave manager hosting the components with SIGKILL: their bindings stay behind. */
    fun killSlave() {
        managers[1].destroyForcibly().waitFor(10, TimeUnit.SECONDS)
    }

    override fun close() {
        witness.close()
        managers.asReversed().forEach { manager ->
            manager.destroy()
            if (!manager.waitFor(10, TimeUnit.SECONDS)) manager.destroyForcibly().waitFor(10, TimeUnit.SECONDS)
        }
        omniNames.close()
        // Slaves the master started are not our children: stop every manager of this run by its configuration file.
        ProcessHandle.allProcesses().filter { process -> process.info().arguments().orElse(emptyArray()).any { it.startsWith(directory.toString()) } }
            .forEach { it.destroyForcibly() }
        directory.toFile().deleteRecursively()
    }

    companion object {
        /** What `rtcd_python` runs: a manager with the command line's options, its components and its loop. */
        private const val RTCD = "import sys, OpenRTM_aist; m = OpenRTM_aist.Manager.init(sys.argv); m.activateManager(); m.runManager()"

        /** The component modules, written for this test. */
        private val components: Path = Paths.get("openrtm-python")

        /** Starts the system, or skips the test when no OpenRTM-aist-Python installation is named. */
        fun start(): OpenRtmPythonSystem {
            val python = System.getenv("RTCOORD_OPENRTM_PYTHON")
            assumeTrue(
                python != null,
                "set RTCOORD_OPENRTM_PYTHON to a Python that imports OpenRTM_aist to run the localisation scenario on real OpenRTM-aist",
            )
            val system = OpenRtmPythonSystem(python!!)
            try {
                system.start()
            } catch (e: Throwable) {
                system.close()
                throw e
            }
            return system
        }
    }
}
