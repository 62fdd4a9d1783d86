package org.rtcoord.sim

import java.net.InetSocketAddress
import java.nio.file.Path
import org.rtcoord.datatypes.IdlFiles
import org.rtcoord.idl.OrbRecipe
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeManager
import org.rtcoord.runtime.naming.NamingService

/**
 * An RT system simulated from an RTSProfile on the runtime (whose fidelity to OpenRTM-aist `runtime/README.md`
 * records), on a naming service of its own: each component of the profile with its ports and their interfaces,
 * configuration sets (hidden ones too) and execution contexts, bound where the profile found it, connected as the
 * profile says and activated, as `rtcoord profile restore` and rtshell's `rtstart` leave a system; and the profile's
 * managers ([ProfileKeys]): the master, and each slave in a process of its own with the components it hosted, creating
 * the types it could.
 *
 * What the profile names that cannot be simulated is left out and said in [warnings], one line each; the rest runs.
 * What the profile cannot tell (the ports of a type the managers can create but no component of the profile is) is said
 * in [notes]. Faults come through the [components] (`breakDown`, `fail`, `hangExecution`, ...), [killManager] and
 * [restartNaming].
 */
public class SimulatedSystem
private constructor(
    private val host: String,
    /** How many request threads each of its ORBs keeps when idle. */
    private val idleRequestThreads: Int,
    @Volatile private var naming: NamingService,
    private val processes: SimulatedProcesses,
    /** What the profile says that could not be simulated, one line each: the element, then why. */
    public val warnings: List<String>,
    /**
     * What the profile cannot tell, one line each: a type its managers can create with no instance in it and no
     * `rtcoord.type.TYPE.port.PORT` properties, whose instances are created without ports. The saved system itself is
     * simulated whole: a test of it does not fail for these.
     */
    public val notes: List<String>,
) : AutoCloseable {
    /** The naming service's `HOST:PORT`, as `rtcoord -n` and rtshell paths (`/HOST:PORT/`) take it. */
    public val address: String
        get() = naming.address

    /** The naming service's `corbaloc:` address. */
    public val corbaloc: String
        get() = naming.corbaloc

    /** The master manager, bound where the profile found it; null when the profile names none. */
    public val manager: RuntimeManager?
        get() = processes.master?.manager

    /** The slave managers, those the master started since included, in the order they joined it. */
    public val slaves: List<RuntimeManager>
        get() = processes.slaves.map { it.manager }

    /**
     * The components alive now, the profile's and those the managers created since, process by process in creation
     * order: a killed manager's are gone.
     */
    public val components: List<RuntimeComponent>
        get() = processes.all.filterNot { it.isKilled }.flatMap { it.components }.filterNot { it.isExited }

    /** The live component named [instanceName]; throws [IllegalArgumentException] naming those there are. */
    public fun component(instanceName: String): RuntimeComponent =
        components.firstOrNull { it.instanceName == instanceName }
            ?: throw IllegalArgumentException(
                "no component $instanceName in the simulated system (components: ${components.joinToString { it.instanceName }.ifEmpty { "none" }})"
            )

    /**
     * Makes its components send their log records ([RuntimeComponent.log]) to the Fluentd forward input at [address],
     * each process naming its manager, as OpenRTM-aist's do when their `rtc.conf` names a fluentd log stream.
     */
    public fun sendLogsTo(address: InetSocketAddress) {
        processes.sendLogsTo(address)
    }

    /** Whether the system has a master manager, and it was not killed. */
    public val hasLiveManager: Boolean
        get() = processes.master?.process?.isKilled == false

    /**
     * Kills the master manager's process, as `kill -9` on `rtcd` would: it stops answering, its name stays bound in
     * naming (a dead reference, as OpenRTM-aist leaves it), nothing can be created through it, and the components it
     * hosted itself die with it. Those of its slaves, in processes of their own, run on. Throws [IllegalStateException]
     * when the system has no live master.
     */
    public fun killManager() {
        val master =
            checkNotNull(processes.master) {
                "the simulated system has no manager (its profile names none: ${ProfileKeys.MANAGER})"
            }
        kill(master, "${master.name}.mgr")
    }

    /**
     * Kills the process of the manager [name], as `kill -9` would: a slave by its name (`localisation`, or
     * `manager.mgr/localisation` as the tree shows it), or the master (`manager` or `manager.mgr`). Every component it
     * hosts dies with it, their names left bound; the master keeps listing a dead slave, as OpenRTM-aist's does, until
     * a call to it fails (`get_components`, `create_component`...), and then drops it. Throws
     * [IllegalArgumentException] when no manager, or more than one, has that name, and [IllegalStateException] when it
     * was killed already.
     */
    public fun killManager(name: String) {
        val master = processes.master
        val masterNames = master?.let { setOf(it.name, "${it.name}.mgr") }.orEmpty()
        val candidates =
            listOfNotNull(master?.takeIf { name in masterNames }) +
                processes.slaves.filter {
                    name == it.name || (master != null && name == "${master.name}.mgr/${it.name}")
                }
        val known =
            listOfNotNull(master?.let { "${it.name}.mgr" }) + processes.slaves.map { "${master?.name}.mgr/${it.name}" }
        when (candidates.size) {
            0 ->
                throw IllegalArgumentException(
                    "no manager $name in the simulated system (managers: ${known.joinToString().ifEmpty { "none" }})"
                )
            1 -> kill(candidates.single(), name)
            else ->
                throw IllegalArgumentException(
                    "$name names more than one manager: say ${master?.name}.mgr for the master, ${master?.name}.mgr/$name for its slave"
                )
        }
    }

    private fun kill(manager: SimulatedManager, name: String) {
        check(!manager.process.isKilled) { "the manager $name was killed already" }
        manager.process.kill()
    }

    /**
     * Stops the naming service and starts it again on the same port with the same bindings, as omniNames restarted from
     * its log does: for the moment between, nothing resolves.
     */
    public fun restartNaming() {
        val bindings = naming.snapshot()
        val port = naming.port
        naming.close()
        naming = NamingService.start(port, bindings, host, idleRequestThreads)
    }

    /** Stops the components, the managers and the naming service. */
    override fun close() {
        processes.close()
        naming.close()
    }

    public companion object {
        /**
         * Simulates the profile in [file] (XML or YAML), its data types declared by OpenRTM-aist or by the IDL files in
         * [idlDirectories]; throws [ProfileFormatException] when the profile cannot be read.
         */
        @JvmStatic
        @JvmOverloads
        @Throws(ProfileFormatException::class)
        public fun start(
            file: Path,
            host: String = "127.0.0.1",
            port: Int = 0,
            idlDirectories: List<Path> = emptyList(),
        ): SimulatedSystem = start(RtsProfiles.read(file), host, port, idlDirectories)

        /**
         * Simulates [profile] with every ORB and the naming service listening on [host], the naming service on [port]
         * (0: a free one), the data types the IDL files in [idlDirectories] declare besides OpenRTM-aist's. What cannot
         * be simulated (an IDL file that cannot be read included: its types' ports send nothing) is left out and named
         * in [warnings]. The system runs [speed] times as fast as the robot's clock
         * ([org.rtcoord.runtime.RuntimeProcess.speed]), for a tree at the same speed (`TreeConfig.speed`).
         */
        @JvmStatic
        @JvmOverloads
        public fun start(
            profile: RtsProfile,
            host: String = "127.0.0.1",
            port: Int = 0,
            idlDirectories: List<Path> = emptyList(),
            speed: Double = 1.0,
        ): SimulatedSystem = start(profile, host, port, idlDirectories, speed, OrbRecipe.REQUEST_THREADS)

        /**
         * As the public [start], each of its ORBs keeping [idleRequestThreads] request threads when idle
         * ([OrbRecipe.properties]): fewer for a system made and closed for each run of a scenario.
         */
        internal fun start(
            profile: RtsProfile,
            host: String,
            port: Int,
            idlDirectories: List<Path>,
            speed: Double,
            idleRequestThreads: Int,
        ): SimulatedSystem {
            val types =
                SimulatedTypes(profile, idlDirectories.takeIf { it.isNotEmpty() }?.let(IdlFiles::readDirectories))
            val simulated = profile.components.map { it.instanceName }.filter { it in types.byInstance }
            val topology = ManagerTopology.of(profile, simulated, types.creatable.keys.toList())
            val warnings = (types.warnings + topology.warnings).toMutableList()
            val naming = NamingService.start(port, host = host, idleRequestThreads = idleRequestThreads)
            val processes =
                try {
                    val recipe = ProcessRecipe(naming.corbaloc, host, speed, idleRequestThreads)
                    SimulatedProcesses.start(recipe, topology, types.creatable, types.byInstance)
                } catch (e: Exception) {
                    naming.close()
                    throw e
                }
            val system = SimulatedSystem(host, idleRequestThreads, naming, processes, warnings, types.notes.toList())
            try {
                if (!profile.ext.properties[ProfileKeys.MANAGER_COMMAND].isNullOrBlank() && processes.master != null) {
                    processes.startSlavesOnDemand(types.creatable.values)
                }
                SimulatedStart(profile, types, processes, warnings).run()
            } catch (e: Exception) {
                system.close()
                throw e
            }
            return system
        }
    }
}
