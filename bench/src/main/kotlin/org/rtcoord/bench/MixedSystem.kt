package org.rtcoord.bench

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.ReturnCode_t
import _SDOPackage.NameValue
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.SystemProfiles
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.ContextSpec
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeManager
import org.rtcoord.runtime.RuntimeModule
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * A robot-shaped system of mixed component types to simulate: groups of ten (a laser, a gyro and odometry feeding a
 * localiser, a map server serving a map client through service ports, two relays in a chain, OpenRTM-aist's
 * ConfigSample with its hidden and constrained sets, and a relay with a second, event-driven context), the sensors in
 * one slave manager's process and the rest in another's, below a master; every context at 20 Hz, as a real system's run
 * at tens of hertz. Saved as `rtcoord profile save` saves it.
 */
internal object MixedSystem {
    private const val RATE = 20.0

    private val sensors =
        listOf(Scenarios.laser, Scenarios.gyro, Scenarios.odometry, Scenarios.mapServer).map { it.at(RATE) }
    private val mapClient =
        ComponentType(
            "map_client",
            listOf(org.rtcoord.runtime.PortSpec.Service("map", required = mapOf("map" to "MapServer::Map"))),
            rate = RATE,
        )
    private val twoContexts =
        Scenarios.relay
            .at(RATE, ContextSpec(RATE), ContextSpec(RATE, ContextSpec.Kind.EVENT_DRIVEN))
            .renamed("relay_ec")
    private val processing =
        listOf(
            Scenarios.laserLocalise.at(RATE),
            mapClient,
            Scenarios.relay.at(RATE),
            Scenarios.configSample.at(RATE),
            twoContexts,
        )

    /** The profile of a system of [size] components (rounded up to whole groups of ten). */
    fun saved(size: Int): RtsProfile =
        NamingService.start().use { naming ->
            val processes = List(3) { RuntimeProcess.start(naming.corbaloc) }
            try {
                val (masterProcess, sensorProcess, processingProcess) = processes
                val master = RuntimeManager(masterProcess, isMaster = true)
                master.adopt(
                    RuntimeManager(
                        sensorProcess,
                        isMaster = false,
                        name = "sensors",
                        modules = listOf(RuntimeModule("sensors.so", sensors)),
                    )
                )
                master.adopt(
                    RuntimeManager(
                        processingProcess,
                        isMaster = false,
                        name = "processing",
                        modules = listOf(RuntimeModule("processing.so", processing)),
                    )
                )
                repeat((size + 9) / 10) { group -> group(group, sensorProcess, processingProcess) }
                kotlinx.coroutines.runBlocking {
                    RtcTree(TreeConfig(listOf(naming.address))).use { SystemProfiles(it).save() }
                }
            } finally {
                processes.forEach(RuntimeProcess::close)
            }
        }

    private fun group(index: Int, sensorProcess: RuntimeProcess, processingProcess: RuntimeProcess) {
        val made =
            sensors.associate { it.typeName to sensorProcess.create(it) } +
                processing.associate { it.typeName to processingProcess.create(it) } +
                ("relay_2" to processingProcess.create(processing[2]))
        val orb = sensorProcess.orb.orb
        connect(orb, made.getValue("laser"), "laser", made.getValue("laser_localise"), "laser")
        connect(orb, made.getValue("odometry"), "odo", made.getValue("laser_localise"), "odo")
        connect(orb, made.getValue("map_server"), "map", made.getValue("map_client"), "map")
        connect(orb, made.getValue("relay"), "out", made.getValue("relay_2"), "in")
        check(made.size == 10) { "group $index has ${made.size} components" }
        made.values.forEach { it.activateEverywhere() }
    }

    private fun connect(
        orb: org.omg.CORBA.ORB,
        from: RuntimeComponent,
        fromPort: String,
        to: RuntimeComponent,
        toPort: String,
    ) {
        val ports =
            listOf(from to fromPort, to to toPort).map { (component, port) ->
                component.ref.get_ports().single { it.get_port_profile().name == "${component.instanceName}.$port" }
            }
        val properties =
            if (fromPort == "map") emptyList()
            else
                listOf(
                    "dataport.dataflow_type" to "push",
                    "dataport.interface_type" to "corba_cdr",
                    "dataport.subscription_type" to "new",
                )
        val values = properties.map { (key, value) -> NameValue(key, orb.create_any().apply { insert_string(value) }) }
        val holder =
            ConnectorProfileHolder(
                ConnectorProfile(
                    "${from.instanceName}_${to.instanceName}",
                    "",
                    ports.toTypedArray(),
                    values.toTypedArray(),
                )
            )
        check(ports[0].connect(holder) == ReturnCode_t.RTC_OK) {
            "connecting ${from.instanceName}.$fromPort to ${to.instanceName}.$toPort"
        }
    }

    private fun ComponentType.at(rate: Double, vararg contexts: ContextSpec): ComponentType =
        ComponentType(
            typeName,
            ports,
            parameters,
            configurationSets,
            behaviour,
            rate,
            observerFlavours,
            vendor,
            category,
            version,
            description,
            fsm,
            contexts.toList().ifEmpty { listOf(ContextSpec(rate)) },
        )

    private fun ComponentType.renamed(name: String): ComponentType =
        ComponentType(
            name,
            ports,
            parameters,
            configurationSets,
            behaviour,
            rate,
            observerFlavours,
            vendor,
            category,
            version,
            description,
            fsm,
            contexts,
        )
}
