package org.rtcoord.sim

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.ReturnCode_t
import _SDOPackage.NameValue
import kotlinx.coroutines.runBlocking
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.SystemProfiles
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.ContextSpec
import org.rtcoord.runtime.ParameterSpec
import org.rtcoord.runtime.PortSpec
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeManager
import org.rtcoord.runtime.RuntimeModule
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * A "live" system on the runtime shaped as real robots are: a master `manager.mgr` with two slaves, each in a process
 * of its own. `sensors` hosts `laser0`, `gyro0`, `odometry0` and `map_server0` (a service port providing `map`);
 * `localisation` hosts `laser_localise0`, `map_client0` (requiring `map`) and `planner0` (a periodic and an
 * event-driven context, a numeric constraint, a hidden widget set), and can load `odo_localise`. The laser and odometry
 * feed the localiser, the map server serves the client; all active.
 */
class TwoSlaveSystem private constructor(private val naming: NamingService) : AutoCloseable {
    private val master = RuntimeProcess.start(naming.corbaloc)
    private val sensors = RuntimeProcess.start(naming.corbaloc)
    private val localisation = RuntimeProcess.start(naming.corbaloc)

    /** The naming service's `host:port`. */
    val address: String
        get() = naming.address

    /** The master manager. */
    val manager = RuntimeManager(master, isMaster = true)

    init {
        manager.adopt(
            RuntimeManager(
                sensors,
                isMaster = false,
                name = "sensors",
                modules =
                    listOf(
                        RuntimeModule(
                            "sensors.so",
                            listOf(Scenarios.laser, Scenarios.gyro, Scenarios.odometry, mapServer),
                        )
                    ),
            )
        )
        val modules =
            listOf(
                RuntimeModule("localisers.so", listOf(Scenarios.laserLocalise, mapClient, planner)),
                RuntimeModule("odo_localise.so", listOf(Scenarios.odoLocalise)),
            )
        manager.adopt(
            RuntimeManager(
                localisation,
                isMaster = false,
                name = "localisation",
                modules = modules,
                preloaded = listOf("localisers.so"),
            )
        )
        listOf(Scenarios.laser, Scenarios.gyro, Scenarios.odometry, mapServer).forEach { sensors.create(it) }
        listOf(Scenarios.laserLocalise, mapClient, planner).forEach { localisation.create(it) }
        connect(
            "laser0:laser",
            "laser_localise0:laser",
            "dataport.dataflow_type" to "push",
            "dataport.interface_type" to "corba_cdr",
            "dataport.subscription_type" to "new",
        )
        connect(
            "odometry0:odo",
            "laser_localise0:odo",
            "dataport.dataflow_type" to "push",
            "dataport.interface_type" to "corba_cdr",
            "dataport.subscription_type" to "flush",
        )
        connect("map_server0:map", "map_client0:map")
        components.forEach { it.activateEverywhere() }
    }

    /** Every component, the sensors' then the localisation's. */
    val components: List<RuntimeComponent>
        get() = sensors.components + localisation.components

    /** Saves the system as `rtcoord profile save` does. */
    fun save(): RtsProfile = runBlocking { tree().use { SystemProfiles(it).save() } }

    /** A tree on the system's naming service; the caller closes it. */
    fun tree(): RtcTree = RtcTree(TreeConfig(nameServers = listOf(address)))

    private fun connect(from: String, to: String, vararg properties: Pair<String, String>) {
        val ports =
            listOf(from, to).map { address ->
                val (instance, port) = address.split(':')
                components
                    .single { it.instanceName == instance }
                    .ref
                    .get_ports()
                    .single { it.get_port_profile().name == "$instance.$port" }
            }
        val orb = sensors.orb.orb
        val values = properties.map { (key, value) -> NameValue(key, orb.create_any().apply { insert_string(value) }) }
        val holder =
            ConnectorProfileHolder(ConnectorProfile("${from}_$to", "", ports.toTypedArray(), values.toTypedArray()))
        check(ports[0].connect(holder) == ReturnCode_t.RTC_OK) { "connecting $from to $to" }
    }

    override fun close() {
        listOf(localisation, sensors, master).forEach(RuntimeProcess::close)
        naming.close()
    }

    companion object {
        /** A map server: service port `map` providing `map` (`MapServer::Map`) and requiring `pose`. */
        val mapServer: ComponentType = Scenarios.mapServer

        /** A map client: service port `map` requiring `map` (`MapServer::Map`). */
        val mapClient =
            ComponentType(
                "map_client",
                listOf(PortSpec.Service("map", required = mapOf("map" to "MapServer::Map"))),
                rate = 10.0,
            )

        /**
         * A planner with a periodic context at 20 Hz and an event-driven one at 5 Hz, and constrained, hidden and extra
         * configuration.
         */
        val planner =
            ComponentType(
                "planner",
                parameters = listOf(ParameterSpec.integer("horizon", 10), ParameterSpec("mode", "safe")),
                configurationSets =
                    mapOf(
                        "fast" to mapOf("horizon" to "3"),
                        "__constraints__" to mapOf("horizon" to "0<=x<=100", "mode" to "(safe,fast)"),
                        "__widget__" to mapOf("horizon" to "slider.1", "mode" to "radio"),
                    ),
                contexts = listOf(ContextSpec(20.0), ContextSpec(5.0, ContextSpec.Kind.EVENT_DRIVEN)),
            )

        /** Starts it on a naming service of its own. */
        fun start(): TwoSlaveSystem {
            val naming = NamingService.start()
            return try {
                TwoSlaveSystem(naming)
            } catch (e: Exception) {
                naming.close()
                throw e
            }
        }
    }
}
