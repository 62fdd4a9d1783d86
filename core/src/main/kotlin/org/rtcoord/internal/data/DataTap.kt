package org.rtcoord.internal.data

import OpenRTM.InPortCdrPOA
import OpenRTM.PortStatus
import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.PortService
import _SDOPackage.NameValue
import java.util.UUID
import java.util.concurrent.CopyOnWriteArrayList
import org.rtcoord.BadParameterException
import org.rtcoord.DataListener
import org.rtcoord.Port
import org.rtcoord.PortData
import org.rtcoord.PortKind
import org.rtcoord.PortSnapshot
import org.rtcoord.RtcException
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.orFail
import org.rtcoord.internal.toMap
import org.slf4j.LoggerFactory

/**
 * The tree's subscription to one out-port's data, as a connected in-port has it: an `InPortCdr` endpoint and a
 * [TapPort] served by [host], connected to the port with OpenRTM's push handshake. The connector holds the out-port and
 * the tap's port, and names the endpoint in `dataport.corba_cdr.inport_ior`, which the out-port's
 * `InPortCorbaCdrConsumer` subscribes to (OpenRTM-aist's `subscribeFromIor`). Its id and name start with [PREFIX], so a
 * later tree can remove the connectors of trees that died (see [removeStaleTaps]). Each sample is decoded once, in the
 * byte order the connector negotiated, and handed to every listener.
 */
internal class DataTap(private val core: TreeCore, private val port: Port, private val host: TapHost) {
    private val log = LoggerFactory.getLogger(DataTap::class.java)
    private val subject = port.path.toString()
    private val listeners = CopyOnWriteArrayList<DataListener>()
    private var endpoints: List<TapHost.Endpoint> = emptyList()
    private var reference: PortService? = null
    @Volatile private var decoder = DataDecoder("", littleEndian = true)

    /** The connector's id once connected. */
    @Volatile
    var connectorId: String? = null
        private set

    fun add(listener: DataListener) {
        listeners += listener
    }

    /** Removes [listener]; returns whether none is left. */
    fun remove(listener: DataListener): Boolean {
        listeners -= listener
        return listeners.isEmpty()
    }

    /** Connects the tap, after removing the stale taps of dead trees from the port. */
    suspend fun connect() {
        val snapshot = port.snapshot()
        if (snapshot.kind != PortKind.DATA_OUT) {
            throw BadParameterException(
                subject,
                "tap",
                "only an out-port's data can be tapped (this is a ${snapshot.kind.name.lowercase().replace('_', ' ')} port)",
            )
        }
        val target = port.reference()
        removeStaleTaps(core, subject, target)
        decoder = DataDecoder(snapshot.dataType.orEmpty(), littleEndian = true)
        val inlet =
            host.serve(
                object : InPortCdrPOA() {
                    override fun put(data: ByteArray): PortStatus = receive(data)
                }
            )
        val tapPort = TapPort(core.orb.orb, "rtcoord_tap.${snapshot.fullName}", snapshot.dataType.orEmpty())
        val portEndpoint = host.serve(tapPort)
        tapPort.reference = RTC.PortServiceHelper.narrow(portEndpoint.reference)
        val served = listOf(inlet, portEndpoint)
        val holder =
            ConnectorProfileHolder(
                ConnectorProfile(
                    "$PREFIX${snapshot.fullName}",
                    PREFIX + UUID.randomUUID(),
                    arrayOf(target, tapPort.reference),
                    properties(snapshot, inlet.ior)
                        .map { (key, value) ->
                            NameValue(key, core.orb.orb.create_any().apply { insert_string(value) })
                        }
                        .toTypedArray(),
                )
            )
        try {
            core.remote
                .call(subject, "connect") { target.connect(holder) }
                .orFail(subject, "connect", "the tree's data tap")
        } catch (e: RtcException) {
            served.forEach(TapHost.Endpoint::close)
            throw e
        }
        val made = holder.value.properties.toMap()
        decoder =
            DataDecoder(
                made["dataport.data_type"] ?: snapshot.dataType.orEmpty(),
                littleEndian(made["dataport.serializer.cdr.endian"]),
            )
        endpoints = served
        reference = target
        connectorId = holder.value.connector_id
        log.debug("{}: tap {} connected", subject, connectorId)
    }

    /** Removes the tap's connector from the port and stops serving its endpoint. */
    suspend fun disconnect() {
        val id = connectorId ?: return
        val target = reference ?: return
        try {
            core.remote
                .call(subject, "disconnect") { target.disconnect(id) }
                .orFail(subject, "disconnect", "the tree's data tap $id")
        } finally {
            forget()
        }
    }

    /** [disconnect] on the calling thread, within the ORB's call deadline; the tree is closing. */
    fun disconnectNow() {
        val id = connectorId ?: return
        try {
            reference?.disconnect(id)
        } catch (e: org.omg.CORBA.SystemException) {
            log.debug("{}: could not remove tap {}: {}", subject, id, e.toString())
        } finally {
            forget()
        }
    }

    private fun forget() {
        endpoints.forEach(TapHost.Endpoint::close)
        endpoints = emptyList()
        connectorId = null
    }

    private fun receive(data: ByteArray): PortStatus {
        val sample: PortData = decoder.decode(data)
        for (listener in listeners) {
            try {
                listener.onData(sample)
            } catch (e: Exception) {
                log.warn("{}: data listener failed: {}", subject, e.toString(), e)
            }
        }
        return PortStatus.PORT_OK
    }

    private fun properties(snapshot: PortSnapshot, ior: String): Map<String, String> {
        val offered =
            snapshot.properties["dataport.subscription_type"]?.split(',')?.map { it.trim().lowercase() }.orEmpty()
        return buildMap {
            put("dataport.dataflow_type", "push")
            put("dataport.interface_type", "corba_cdr")
            // "new" sends the newest sample from a thread of the publisher's own: a slow tap never slows the component.
            put("dataport.subscription_type", if ("new" in offered) "new" else "flush")
            snapshot.dataType?.let { put("dataport.data_type", it) }
            // What OpenRTM-aist's InPortBase.connect offers; the out-port keeps the first it supports.
            put("dataport.serializer.cdr.endian", "little,big")
            put("dataport.corba_cdr.inport_ior", ior)
        }
    }

    companion object {
        /** Every tap connector's id and name start with it. */
        const val PREFIX = "rtcoord-tap-"

        /**
         * The byte order a connector's `dataport.serializer.cdr.endian` settled on: its first entry, little by default.
         */
        fun littleEndian(endian: String?): Boolean = endian?.split(',')?.firstOrNull()?.trim()?.lowercase() != "big"
    }
}
