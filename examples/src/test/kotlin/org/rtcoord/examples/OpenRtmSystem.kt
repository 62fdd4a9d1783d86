package org.rtcoord.examples

import java.net.InetAddress
import java.net.ServerSocket
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.fixtures.OmniNames
import org.rtcoord.fixtures.awaitValue

/**
 * The paper's localisation system on a real OpenRTM-aist [installation]: omniNames, a master manager and a slave
 * manager, the slave hosting `laser0`, `gyro0`, `odometry0` and `laser_localise0` from the installation's modules, with
 * `odo_localise`'s module loadable but not loaded. Connected and activated as the fixtures' localisation system is. The
 * master's `manager_cmd` starts another slave when it has none that can create a component, as the implementation's own
 * daemon would.
 */
class OpenRtmSystem private constructor(val installation: OpenRtmInstallation) : AutoCloseable {
    /** The system's own directory (configuration files, logs, what a test puts there): deleted on [close]. */
    val directory: Path = Files.createTempDirectory("rtcoord-openrtm")
    private val omniNames = OmniNames.start()
    private val masterPort = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { it.localPort }
    private val managers = mutableListOf<Process>()
    private val common: List<String> = commonLines()
    val witness: RtcTree = RtcTree(TreeConfig(nameServers = listOf(omniNames.address)))

    /** The naming service's address (`host:port`), for the coordinator's tree. */
    val naming: String
        get() = omniNames.address

    /** The naming context the components bind in: OpenRTM's `%h.host_cxt` for this host. */
    lateinit var context: String
        private set

    /** The path of [name] (`laser0.rtc`, `laser0.rtc:laser`) in the components' context. */
    fun path(name: String): String = "$context/$name"

    /**
     * What every manager of this system reads, from its own configuration file, and from `shared.conf` when the master
     * starts it through the installation's `manager_cmd` (OpenRTM-aist C++ passes a slave it starts no configuration
     * file of its own).
     */
    private fun commonLines(): List<String> {
        val file = directory.resolve("shared.conf")
        val lines =
            listOf(
                "corba.nameservers: ${omniNames.address}",
                "corba.endpoints: 127.0.0.1",
                "corba.master_manager: 127.0.0.1:$masterPort",
                "manager.naming_formats: %h.host_cxt/%n.mgr",
                "naming.formats: %h.host_cxt/%n.rtc",
                "logger.enable: YES",
                "logger.log_level: WARN",
            ) + installation.sharedLines(directory, file)
        Files.write(file, lines + "logger.file_name: ${directory.resolve("started%p.log")}")
        return lines
    }

    private fun start() {
        val types = listOf("laser", "gyro", "odometry", "laser_localise")
        managers +=
            manager(
                "master",
                directory,
                installation.loadPath,
                "manager.is_master: YES",
                "manager.instance_name: manager",
            )
        // A slave joins the master it finds when it starts: the master must be up by then.
        runBlocking {
            awaitValue("the master manager in naming", 30.seconds) {
                runBlocking {
                    runCatching {
                        witness.refresh()
                        witness.find().toList().firstOrNull { it.name == "manager.mgr" }
                    }
                        .getOrNull()
                }
            }
        }
        // The slave runs in the modules' directory: a Python module imports what they share from there.
        managers +=
            manager(
                "slave",
                installation.components,
                installation.loadPath,
                "manager.is_master: NO",
                "manager.modules.preload: ${types.joinToString(", ") { installation.module(it) }}",
                "manager.components.precreate: ${types.joinToString(", ")}",
                "exec_cxt.periodic.rate: 20",
                *installation.slaveLines.toTypedArray(),
            )
        runBlocking {
            // All four, each at its naming path: the slave binds them one by one, and a read in between
            // finds some missing, or some only in the manager's listing.
            val laser =
                awaitValue("the slave's components in naming", 30.seconds) {
                    runBlocking {
                        runCatching {
                            witness.refresh()
                            types
                                .map { witness.componentNamed("${it}0.rtc").canonicalPath }
                                .takeIf { paths -> paths.none { path -> path.names.any { it.endsWith(".mgr") } } }
                        }
                            .getOrNull()
                            ?.first()
                    }
                }
            context = laser.parent.toString()
            witness.connect(path("laser0.rtc:laser"), path("laser_localise0.rtc:laser"))
            witness.connect(path("odometry0.rtc:odo"), path("laser_localise0.rtc:odo"))
            listOf("laser0", "gyro0", "odometry0", "laser_localise0").forEach {
                witness.component(path("$it.rtc")).activate()
            }
        }
    }

    /**
     * Starts the installation's daemon as the manager [role] in [workingDirectory], loading modules from [loadPath],
     * with these configuration lines after the common ones.
     */
    private fun manager(role: String, workingDirectory: Path, loadPath: List<Path>, vararg lines: String): Process {
        val conf = directory.resolve("$role.conf")
        val own =
            listOf(
                "logger.file_name: ${directory.resolve("$role.log")}",
                "manager.modules.load_path: ${loadPath.joinToString(", ")}",
            )
        Files.write(conf, common + own + lines)
        return ProcessBuilder(installation.daemon(conf))
            .directory(workingDirectory.toFile())
            .redirectErrorStream(true)
            .redirectOutput(directory.resolve("$role.out").toFile())
            .start()
    }

    /**
     * Starts a manager of its own, no slave of the master, loading modules from [loadPath], with these configuration
     * lines (its modules, its components), and waits until the components [instances] name are in naming. Its master is
     * an address nobody listens at: it stays on its own, so the master never hands it a creation.
     */
    fun startOwnManager(role: String, loadPath: List<Path>, instances: List<String>, vararg lines: String) {
        val loose = ServerSocket(0, 1, InetAddress.getLoopbackAddress()).use { it.localPort }
        managers +=
            manager(
                role,
                directory,
                loadPath,
                "corba.master_manager: 127.0.0.1:$loose",
                "manager.is_master: NO",
                *lines,
            )
        runBlocking {
            awaitValue("${instances.joinToString(" and ")} in naming", 30.seconds) {
                runBlocking {
                    runCatching {
                        witness.refresh()
                        instances.forEach { witness.componentNamed("$it.rtc") }
                    }
                        .getOrNull()
                }
            }
        }
    }

    /**
     * Starts another slave of the master, [name], in [workingDirectory], loading modules from [loadPath], with these
     * configuration lines (its modules, its components), and waits until the master lists it and the components
     * [instances] name are in naming. A C++ slave carries its master's `manager.name`; its instance name is [name], as
     * a Python slave's is.
     */
    fun startSlave(
        name: String,
        workingDirectory: Path,
        loadPath: List<Path>,
        instances: List<String>,
        vararg lines: String,
    ) {
        managers +=
            manager(
                name,
                workingDirectory,
                loadPath,
                "manager.is_master: NO",
                "manager.name: manager",
                "manager.instance_name: $name",
                *lines,
            )
        runBlocking {
            awaitValue("$name below the master and ${instances.joinToString(" and ")} in naming", 30.seconds) {
                runBlocking {
                    runCatching {
                        witness.refresh()
                        instances.forEach { witness.componentNamed("$it.rtc") }
                        witness.manager(path("manager.mgr")).children().firstOrNull { it.name == name }
                    }
                        .getOrNull()
                }
            }
        }
    }

    /** What the manager [role] (`slave`, `fsm`, ...) and its components printed so far. */
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
        // Slaves the master started are not our children: stop every manager of this run by the files it was given.
        ProcessHandle.allProcesses()
            .filter { process ->
                process.info().arguments().orElse(emptyArray()).any { it.contains(directory.toString()) }
            }
            .forEach { it.destroyForcibly() }
        directory.toFile().deleteRecursively()
    }

    companion object {
        /** Starts the system on [installation]. */
        fun start(installation: OpenRtmInstallation): OpenRtmSystem {
            val system = OpenRtmSystem(installation)
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
