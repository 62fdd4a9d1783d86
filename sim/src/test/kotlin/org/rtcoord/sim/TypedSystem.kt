package org.rtcoord.sim

import java.nio.file.Path
import java.nio.file.Paths
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles

/**
 * A saved system whose ports carry OpenRTM-aist's device types, a user's own type (`Acme::Sensing::Status`, whose IDL
 * is in [acmeIdl]) and a type nobody gave the IDL of (`IDL:Mystery/Blob:1.0`), each source at 100 Hz; `viewer0` takes
 * the pose and the mystery blobs.
 */
internal object TypedSystem {
    val acmeIdl: Path = Paths.get(TypedSystem::class.java.getResource("/idl/acme")!!.toURI())

    /** Out-port name and type of each source component, by instance. */
    val sources: Map<String, Pair<String, String>> =
        linkedMapOf(
            "odometry0" to ("odo" to "IDL:RTC/TimedPose2D:1.0"),
            "ranger0" to ("range" to "IDL:RTC/RangeData:1.0"),
            "camera0" to ("image" to "IDL:RTC/CameraImage:1.0"),
            "cloud0" to ("cloud" to "IDL:RTC/PointCloud:1.0"),
            "acme0" to ("status" to "IDL:Acme/Sensing/Status:1.0"),
            "mystery0" to ("blob" to "IDL:Mystery/Blob:1.0"),
        )

    /** The profile, with [extraConnectors] (source port, target port, type) besides pose and blob to the viewer. */
    fun profile(extraConnectors: List<Triple<String, String, String>> = emptyList()): RtsProfile {
        val components =
            sources.map { (instance, port) ->
                component(instance, listOf(Triple(port.first, "DataOutPort", port.second)))
            } +
                component(
                    "viewer0",
                    listOf(
                        Triple("pose", "DataInPort", "IDL:RTC/TimedPose2D:1.0"),
                        Triple("blob", "DataInPort", "IDL:Mystery/Blob:1.0"),
                    ),
                )
        val connectors =
            listOf(
                Triple("odometry0.odo", "viewer0.pose", "IDL:RTC/TimedPose2D:1.0"),
                Triple("mystery0.blob", "viewer0.blob", "IDL:Mystery/Blob:1.0"),
            ) + extraConnectors
        val xml =
            """<?xml version="1.0" encoding="UTF-8"?>
            |<rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rts:id="RTSystem:rtcoord:Typed:0" rts:abstract="" rts:creationDate="2026-11-28T00:00:00" rts:updateDate="2026-11-28T00:00:00" rts:version="0.2">
            |${components.joinToString("\n")}
            |${connectors.mapIndexed { index, (source, target, type) -> connector(index, source, target, type) }.joinToString("\n")}
            |</rts:RtsProfile>
        """
                .trimMargin()
        return RtsProfiles.parse(xml, ProfileFormat.XML)
    }

    private fun component(instance: String, ports: List<Triple<String, String, String>>): String {
        val path = "127.0.0.1:2809/vm.host_cxt/$instance.rtc"
        return """<rts:Components xsi:type="rtsExt:component_ext" rts:id="RTC:acme:sensor:${instance.dropLast(1)}:1.0.0" rts:pathUri="$path" rts:activeConfigurationSet="default" rts:instanceName="$instance" rts:compositeType="None" rts:isRequired="true">
            |${ports.joinToString("\n") { (name, kind, type) -> dataPort(name, kind, type) }}
            |<rts:ExecutionContexts xsi:type="rtsExt:execution_context_ext" rts:id="0" rts:kind="PERIODIC" rts:rate="100.0"/>
            |</rts:Components>
        """
            .trimMargin()
    }

    private fun dataPort(name: String, kind: String, type: String) =
        """<rts:DataPorts xsi:type="rtsExt:dataport_ext" rts:name="$name">
        |<rtsExt:Properties rtsExt:name="port.port_type" rtsExt:value="$kind"/>
        |<rtsExt:Properties rtsExt:name="dataport.data_type" rtsExt:value="$type"/>
        |</rts:DataPorts>
    """
            .trimMargin()

    private fun connector(index: Int, source: String, target: String, type: String) =
        """<rts:DataPortConnectors xsi:type="rtsExt:dataport_connector_ext" rts:connectorId="connector-$index" rts:name="${source}_$target" rts:dataType="$type" rts:interfaceType="corba_cdr" rts:dataflowType="push" rts:subscriptionType="new">
        |<rts:sourceDataPort xsi:type="rtsExt:target_port_ext" rts:componentId="RTC:acme:sensor:x:1.0.0" rts:instanceName="${source.substringBefore('.')}" rts:portName="$source"/>
        |<rts:targetDataPort xsi:type="rtsExt:target_port_ext" rts:componentId="RTC:acme:sensor:x:1.0.0" rts:instanceName="${target.substringBefore('.')}" rts:portName="$target"/>
        |<rtsExt:Properties rtsExt:name="dataport.dataflow_type" rtsExt:value="push"/>
        |<rtsExt:Properties rtsExt:name="dataport.interface_type" rtsExt:value="corba_cdr"/>
        |<rtsExt:Properties rtsExt:name="dataport.subscription_type" rtsExt:value="new"/>
        |<rtsExt:Properties rtsExt:name="dataport.data_type" rtsExt:value="$type"/>
        |</rts:DataPortConnectors>
    """
            .trimMargin()
}
