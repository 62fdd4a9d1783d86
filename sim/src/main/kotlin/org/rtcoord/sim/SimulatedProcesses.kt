package org.rtcoord.sim

import java.net.InetSocketAddress
import java.util.concurrent.CopyOnWriteArrayList
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.RuntimeManager
import org.rtcoord.runtime.RuntimeModule
import org.rtcoord.runtime.RuntimeProcess

/**
 * The processes of a simulated system, as [ManagerTopology] lays them out: the master manager's (with the components it
 * hosts), one per slave (a slave and its components die together), one for the components no recorded manager hosts,
 * and the slaves the master starts later with its command.
 */
internal class SimulatedProcesses
private constructor(
    private val recipe: ProcessRecipe,
    val master: SimulatedManager?,
    slaves: List<SimulatedManager>,
    /** The process of the components no manager hosts; null when there are none. */
    private val loose: RuntimeProcess?,
) : AutoCloseable {
    private val slaveList = CopyOnWriteArrayList(slaves)

    /** The slaves, those the master started included, in the order they joined. */
    val slaves: List<SimulatedManager>
        get() = slaveList.toList()

    /** Every process, live or killed. */
    val all: List<RuntimeProcess>
        get() = listOfNotNull(master?.process, loose) + slaveList.map { it.process }

    /** The process the profile placed [instanceName] in: its manager's, or the one no manager owns. */
    fun processFor(instanceName: String): RuntimeProcess =
        (listOfNotNull(master) + slaveList).firstOrNull { instanceName in it.hosts }?.process
            ?: checkNotNull(loose) { "no process hosts $instanceName" }

    /** Where every process sends its components' log records, those of slaves started later too; null: nowhere. */
    @Volatile private var logs: InetSocketAddress? = null

    /** Makes every process, and every slave started later, send its components' log records to [address]. */
    fun sendLogsTo(address: InetSocketAddress) {
        logs = address
        master?.sendLogsTo(address)
        slaveList.forEach { it.sendLogsTo(address) }
        loose?.sendLogsTo(address, LOOSE_MANAGER)
    }

    /**
     * Makes the master start a slave when none of its slaves can create a type, as OpenRTM-aist's runs its
     * `manager_cmd`: a new process whose slave can load every one of [types].
     */
    fun startSlavesOnDemand(types: Collection<ComponentType>) {
        val master = checkNotNull(master) { "no master to start slaves" }
        master.manager.managerCommand = { requested ->
            // `%p` is the new process's pid: here the JVM's, followed by a count.
            val name = requested.replace("%p", "${ProcessHandle.current().pid()}${slaveList.size + 1}")
            val slave = SimulatedManager.start(recipe, name, types, loaded = emptySet(), hosts = emptyList())
            logs?.let(slave::sendLogsTo)
            slaveList += slave
            master.manager.adopt(slave.manager)
        }
    }

    override fun close() {
        (slaveList.map { it.process } + listOfNotNull(loose, master?.process)).forEach(RuntimeProcess::close)
    }

    companion object {
        /** The manager a process of components no manager hosts names in its records: OpenRTM-aist's default. */
        const val LOOSE_MANAGER = "manager"

        /**
         * Starts the processes of [topology] as [recipe] says: each slave can create the types it lists (looked up in
         * [types]), those of the components it hosts ([instances] says which) loaded from the start.
         */
        fun start(
            recipe: ProcessRecipe,
            topology: ManagerTopology,
            types: Map<String, ComponentType>,
            instances: Map<String, ComponentType>,
        ): SimulatedProcesses {
            val started = mutableListOf<RuntimeProcess>()
            try {
                val master =
                    topology.masterPath?.let { path ->
                        val process = recipe.start(path.dropLast(1)).also(started::add)
                        SimulatedManager(
                            RuntimeManager(process, isMaster = true, name = topology.masterName!!),
                            process,
                            topology.masterComponents,
                        )
                    }
                val slaves =
                    topology.slaves.map { slave ->
                        val loaded = (slave.types + slave.components.mapNotNull { instances[it]?.typeName }).toSet()
                        val known = (loaded + slave.loadable).mapNotNull(types::get)
                        SimulatedManager.start(recipe, slave.name, known, loaded, slave.components).also {
                            started += it.process
                        }
                    }
                slaves.forEach { master?.manager?.adopt(it.manager) }
                val loose = if (topology.unhosted.isEmpty() && master != null) null else recipe.start()
                return SimulatedProcesses(recipe, master, slaves, loose)
            } catch (e: Exception) {
                started.forEach(RuntimeProcess::close)
                throw e
            }
        }
    }
}

/** A manager of a simulated system and the process it lives in: [hosts] are the components the profile placed there. */
internal class SimulatedManager(val manager: RuntimeManager, val process: RuntimeProcess, val hosts: List<String>) {
    val name: String
        get() = manager.name

    /** Makes its process send its components' log records to [address], naming this manager. */
    fun sendLogsTo(address: InetSocketAddress) = process.sendLogsTo(address, name)

    companion object {
        /**
         * Starts a slave [name] in a process of its own, hosting [hosts], with a module `<type>.so` for each of
         * [types], of which those [loaded] names are loaded, started as [recipe] says.
         */
        fun start(
            recipe: ProcessRecipe,
            name: String,
            types: Collection<ComponentType>,
            loaded: Set<String>,
            hosts: List<String>,
        ): SimulatedManager {
            val modules = types.map { RuntimeModule("${it.typeName}.so", listOf(it)) }
            val preloaded = modules.filter { it.types.single().typeName in loaded }.map { it.fileName }
            val process = recipe.start()
            return try {
                SimulatedManager(
                    RuntimeManager(process, isMaster = false, name = name, modules = modules, preloaded = preloaded),
                    process,
                    hosts,
                )
            } catch (e: Exception) {
                process.close()
                throw e
            }
        }
    }
}
