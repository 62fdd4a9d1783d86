package org.rtcoord.runtime

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.ReturnCode_t
import java.util.concurrent.CopyOnWriteArrayList

/**
 * A running RT system of runtime components: its processes, and the master and slave manager when it has them.
 * Components live in the slave's runtime when there is a manager, so they are reachable both through naming and below
 * the manager, as with OpenRTM.
 */
public class RtSystem
internal constructor(
    /** The `corbaloc:` address of the naming service the system registers with. */
    public val naming: String,
    public val runtime: RuntimeProcess,
    public val master: RuntimeManager?,
    public val slave: RuntimeManager?,
    private val masterRuntime: RuntimeProcess?,
) : AutoCloseable {
    private val started = CopyOnWriteArrayList<RuntimeManager>()

    /** The slave managers the master started (see [startSlavesOnDemand]), in order. */
    public val startedSlaves: List<RuntimeManager>
        get() = started.toList()

    /**
     * Gives the master a `manager_cmd`: it starts a new slave "process" (a runtime of its own, loading [modules]) when
     * none of its slaves can create a component, as OpenRTM-aist's master does.
     */
    public fun startSlavesOnDemand(modules: List<RuntimeModule>) {
        val master = checkNotNull(master) { "the system has no master manager" }
        master.managerCommand = { requested ->
            val slaveRuntime = RuntimeProcess.start(naming, host = runtime.orb.host)
            // `%p` is the new process's pid; here, the JVM's followed by a count.
            val name = requested.replace("%p", "${ProcessHandle.current().pid()}${started.size + 1}")
            val slave =
                RuntimeManager(slaveRuntime, isMaster = false, name = name, modules = modules, preloaded = emptyList())
            started += slave
            slave.add_master_manager(master.ref)
            master.ref.add_slave_manager(slave.ref)
        }
    }

    /** The component named [instanceName]. */
    public fun component(instanceName: String): RuntimeComponent = runtime.component(instanceName)

    /** All components, in creation order. */
    public val components: List<RuntimeComponent>
        get() = runtime.components

    /**
     * Connects out-port [from] to in-port [to], both as `instance:port`, through the ports' own `connect` as a tool
     * would, with OpenRTM's usual data port properties. Returns the connector id.
     */
    public fun connect(
        from: String,
        to: String,
        name: String = "${from.replace(':', '.')}_${to.replace(':', '.')}",
    ): String {
        val ports =
            listOf(from, to).map { address ->
                val (instance, port) =
                    address.split(':').also { require(it.size == 2) { "not instance:port: $address" } }
                component(instance).ref.get_ports().firstOrNull { it.get_port_profile().name == "$instance.$port" }
                    ?: throw IllegalArgumentException("$instance has no port $port")
            }
        val dataType = ports[0].get_port_profile().properties.first { it.name == "dataport.data_type" }.stringValue()
        val properties =
            mapOf(
                    "dataport.dataflow_type" to "push",
                    "dataport.interface_type" to "corba_cdr",
                    "dataport.subscription_type" to "new",
                    "dataport.data_type" to dataType,
                )
                .map { (key, value) -> component(from.substringBefore(':')).nameValue(key, value) }
        val holder = ConnectorProfileHolder(ConnectorProfile(name, "", ports.toTypedArray(), properties.toTypedArray()))
        val result = ports[0].connect(holder)
        check(result == ReturnCode_t.RTC_OK) { "connecting $from to $to failed: ${result.value()}" }
        return holder.value.connector_id
    }

    /** Stops every runtime: components exit, ORBs close. */
    override fun close() {
        runtime.close()
        started.forEach { it.runtime.close() }
        masterRuntime?.close()
    }
}

/** Declares what an [RtSystem] holds before it starts. */
public class SystemBuilder internal constructor() {
    internal val components = mutableListOf<Triple<ComponentType, String?, List<String>?>>()
    internal val connections = mutableListOf<Pair<String, String>>()
    internal val active = mutableListOf<String>()
    internal var modules: List<RuntimeModule>? = null
    internal var preloaded: List<String>? = null

    /**
     * Adds an instance of [type], named [name] or by OpenRTM's rule, bound under [contexts] (default: the host
     * context).
     */
    public fun component(type: ComponentType, name: String? = null, contexts: List<String>? = null) {
        components += Triple(type, name, contexts)
    }

    /** Connects out-port [from] to in-port [to], as `instance:port`. */
    public fun connect(from: String, to: String) {
        connections += from to to
    }

    /** Activates these components once everything is connected. */
    public fun activate(vararg names: String) {
        active += names
    }

    /**
     * Starts a master manager and a slave that can load these modules, of which those named in [preload] (all by
     * default) are loaded at start; the components are hosted by the slave.
     */
    public fun manager(vararg modules: RuntimeModule, preload: List<String> = modules.map { it.fileName }) {
        this.modules = modules.toList()
        this.preloaded = preload
    }
}

/** Starts the system [declare] describes, listening on [host], registered with the naming service at [naming]. */
public fun rtSystem(naming: String, host: String = "127.0.0.1", declare: SystemBuilder.() -> Unit): RtSystem {
    val plan = SystemBuilder().apply(declare)
    val runtime = RuntimeProcess.start(naming, host = host)
    val masterRuntime = plan.modules?.let { RuntimeProcess.start(naming, host = host) }
    val system =
        try {
            val master = masterRuntime?.let { RuntimeManager(it, isMaster = true) }
            val slave =
                plan.modules?.let {
                    RuntimeManager(
                        runtime,
                        isMaster = false,
                        name = "manager_slave",
                        modules = it,
                        preloaded = plan.preloaded ?: it.map { m -> m.fileName },
                    )
                }
            if (master != null && slave != null) master.adopt(slave)
            RtSystem(naming, runtime, master, slave, masterRuntime)
        } catch (e: Exception) {
            runtime.close()
            masterRuntime?.close()
            throw e
        }
    try {
        for ((type, name, contexts) in plan.components) {
            runtime.create(type, name ?: runtime.nextName(type.typeName), contexts = contexts ?: runtime.contexts)
        }
        plan.connections.forEach { (from, to) -> system.connect(from, to) }
        plan.active.forEach { name ->
            val result = system.component(name).activate()
            check(result == ReturnCode_t.RTC_OK) { "activating $name failed: ${result.value()}" }
        }
    } catch (e: Exception) {
        system.close()
        throw e
    }
    return system
}
