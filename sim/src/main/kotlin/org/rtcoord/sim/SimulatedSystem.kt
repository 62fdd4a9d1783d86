package org.rtcoord.sim

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.ReturnCode_t
import _SDOPackage.NameValue
import org.rtcoord.datatypes.IdlFiles
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeManager
import org.rtcoord.runtime.RuntimeModule
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.naming.NamingService
import java.nio.file.Path

/**
 * An RT system simulated from an RTSProfile on the runtime (whose fidelity to OpenRTM-aist
 * `runtime/README.md` records), on a naming service of its own: each component of the
 * profile with its ports, configuration sets and execution context rate, bound where the profile
 * found it, connected as the profile says and activated, as `rtcoord profile restore` and rtshell's
 * `rtstart` leave a system; and the profile's manager ([ProfileKeys]), which can create the types it names.
 *
 * Faults come through the [components] (`breakDown`, `fail`, `hangExecution`, ...), [killManager] and
 * [restartNaming].
 */
public class SimulatedSystem private constructor(
    private val host: String,
    @Volatile private var naming: NamingService,
    private val runtime: RuntimeProcess,
    private val managerRuntime: RuntimeProcess?,
    /** The master manager, bound where the profile found it; null when the profile names none. */
    public val manager: RuntimeManager?,
    /** What the profile says that could not be simulated, one line each. */
    public val warnings: List<String>,
) : AutoCloseable {
    /** The naming service's `HOST:PORT`, as `rtcoord -n` and rtshell paths (`/HOST:PORT/`) take it. */
    public val address: String get() = naming.address

    /** The naming service's `corbaloc:` address. */
    public val corbaloc: String get() = naming.corbaloc

    /** The components alive now, the profile's and those the manager created since, in creation order. */
    public val components: List<RuntimeComponent> get() = runtime.components.filterNot { it.isExited }

    /** The live component named [instanceName]; throws [IllegalArgumentException] naming those there are. */
    public fun component(instanceName: String): RuntimeComponent = components.firstOrNull { it.instanceName == instanceName }
        ?: throw IllegalArgumentException("no component $instanceName in the simulated system (components: ${components.joinToString { it.instanceName }.ifEmpty { "none" }})")

    /** Whether the system has a manager, and it was not killed. */
    public val hasLiveManager: Boolean get() = managerRuntime != null && !managerKilled

    @Volatile private var managerKilled = false

    /**
     * Kills the master manager's process, as `kill -9` on `rtcd` would: it stops answering, its name
     * stays bound in naming (a dead reference, as OpenRTM-aist leaves it), and nothing can be created
     * through it. The components, hosted by the slave, run on. Throws [IllegalStateException] when the
     * system has no live manager.
     */
    public fun killManager() {
        val manager = checkNotNull(managerRuntime) { "the simulated system has no manager (its profile names none: ${ProfileKeys.MANAGER})" }
        check(!managerKilled) { "the manager was killed already" }
        managerKilled = true
        manager.close()
    }

    /**
     * Stops the naming service and starts it again on the same port with the same bindings, as omniNames
     * restarted from its log does: for the moment between, nothing resolves.
     */
    public fun restartNaming() {
        val bindings = naming.snapshot()
        val port = naming.port
        naming.close()
        naming = NamingService.start(port, bindings, host)
    }

    /** Stops the components, the managers and the naming service. */
    override fun close() {
        runtime.close()
        managerRuntime?.close()
        naming.close()
    }

    public companion object {
        /**
         * Simulates the profile in [file] (XML or YAML), its data types declared by OpenRTM-aist or by the
         * IDL files in [idlDirectories]; throws [ProfileFormatException] when the profile cannot be read.
         */
        @JvmStatic
        @JvmOverloads
        @Throws(ProfileFormatException::class)
        public fun start(file: Path, host: String = "127.0.0.1", port: Int = 0, idlDirectories: List<Path> = emptyList()): SimulatedSystem =
            start(RtsProfiles.read(file), host, port, idlDirectories)

        /**
         * Simulates [profile] with every ORB and the naming service listening on [host], the naming
         * service on [port] (0: a free one), the data types the IDL files in [idlDirectories] declare
         * besides OpenRTM-aist's (an IDL file that cannot be read is a warning: its types' ports send
         * nothing). Throws [IllegalArgumentException] naming the element of the profile that cannot be
         * simulated.
         */
        @JvmStatic
        @JvmOverloads
        public fun start(profile: RtsProfile, host: String = "127.0.0.1", port: Int = 0, idlDirectories: List<Path> = emptyList()): SimulatedSystem {
            val types = SimulatedTypes(profile, idlDirectories.takeIf { it.isNotEmpty() }?.let(IdlFiles::readDirectories))
            val naming = NamingService.start(port, host = host)
            val managerPath = profile.ext.properties[ProfileKeys.MANAGER]?.let(::namingPath)
            val runtime = RuntimeProcess.start(naming.corbaloc, host = host)
            val managerRuntime = managerPath?.let { RuntimeProcess.start(naming.corbaloc, contexts = it.dropLast(1), host = host) }
            val master = try {
                if (managerPath == null || managerRuntime == null) null else RuntimeManager(managerRuntime, isMaster = true, name = managerPath.last().removeSuffix(".mgr"))
            } catch (e: Exception) {
                listOfNotNull(runtime, managerRuntime, naming).forEach(AutoCloseable::close)
                throw e
            }
            val system = SimulatedSystem(host, naming, runtime, managerRuntime, master, types.warnings)
            try {
                if (master != null) {
                    val modules = types.creatable.values.map { RuntimeModule("${it.typeName}.so", listOf(it)) }
                    master.adopt(RuntimeManager(runtime, isMaster = false, name = "manager_slave", modules = modules))
                }
                for (component in profile.components) {
                    val created = runtime.create(types.byInstance.getValue(component.instanceName), component.instanceName, contexts = namingPath(component.pathUri).dropLast(1))
                    val set = component.activeConfigurationSet
                    if (set.isNotEmpty() && set != "default") {
                        require(created.ref.get_configuration().activate_configuration_set(set)) { "${component.instanceName}: cannot activate configuration set $set" }
                    }
                }
                (profile.dataPortConnectors - types.mismatchedConnectors + profile.servicePortConnectors).forEach(system::connect)
                for (component in system.components) {
                    val result = component.activate()
                    check(result == ReturnCode_t.RTC_OK) { "${component.instanceName}: activating it failed: ${result.value()}" }
                }
            } catch (e: Exception) {
                system.close()
                throw e
            }
            return system
        }

        /** The naming contexts and name of a profile path, `host:port/ctx.host_cxt/name.rtc`, without its name server. */
        private fun namingPath(pathUri: String): List<String> {
            val names = pathUri.trim('/').split('/').drop(1)
            require(names.isNotEmpty()) { "path $pathUri names no object below its name server" }
            return names
        }
    }

    /** Connects [connector]'s ports through the first one's `connect`, as rtshell's `rtcon` and `rtresurrect` do. */
    private fun connect(connector: PortConnector) {
        val ends = listOf(connector.source, connector.target)
        val ports = ends.map { end ->
            val component = components.firstOrNull { it.instanceName == end.instanceName }
                ?: throw IllegalArgumentException("connector ${connector.name}: no component ${end.instanceName} in the profile")
            component.ref.get_ports().firstOrNull { it.get_port_profile().name == end.portName }
                ?: throw IllegalArgumentException("connector ${connector.name}: ${end.instanceName} has no port ${end.portName}")
        }
        val orb = runtime.orb.orb
        val properties = connector.connectionProperties().map { (key, value) -> NameValue(key, orb.create_any().apply { insert_string(value) }) }
        val holder = ConnectorProfileHolder(ConnectorProfile(connector.name, connector.connectorId, ports.toTypedArray(), properties.toTypedArray()))
        val result = ports[0].connect(holder)
        require(result == ReturnCode_t.RTC_OK) { "connector ${connector.name} (${ends.joinToString(" to ") { it.portName.orEmpty() }}): connect answered ${result.value()}" }
    }
}
