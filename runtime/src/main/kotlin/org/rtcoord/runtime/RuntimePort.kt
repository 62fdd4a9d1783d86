package org.rtcoord.runtime

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.PortInterfacePolarity
import RTC.PortInterfaceProfile
import RTC.PortProfile
import RTC.PortService
import RTC.PortServiceHelper
import RTC.PortServicePOA
import RTC.ReturnCode_t
import _SDOPackage.NameValue
import java.util.UUID
import java.util.concurrent.ConcurrentHashMap
import org.omg.CORBA.portable.InputStream
import org.omg.CORBA.portable.OutputStream
import org.omg.CORBA.portable.ResponseHandler
import org.rtcoord.datatypes.DataTypeName
import org.slf4j.LoggerFactory

/**
 * A component's port. `connect` follows OpenRTM's handshake: the connecting port fills in an empty connector id (an id
 * it holds already is refused) and calls `notify_connect` on the first port of the profile; each port refuses a peer it
 * is connected to already (unless the connector says `dataport.allow_dup_connection=YES`), publishes its endpoint,
 * passes the profile on to the next port, subscribes to what the others published, and records the connector.
 * Disconnecting walks the same chain, from its first port that answers.
 */
internal class RuntimePort(val spec: PortSpec, private val component: RuntimeComponent) : PortServicePOA() {
    private val log = LoggerFactory.getLogger(RuntimePort::class.java)
    private val connectors = ConcurrentHashMap<String, ConnectorProfile>()
    private val publishers = ConcurrentHashMap<String, Publisher>()
    private val inlets = ConcurrentHashMap<String, InPortServant>()
    @Volatile private var latestSample: Sample? = null

    /** The port's name as OpenRTM reports it: `<instance>.<port>`. */
    val fullName: String = "${component.instanceName}.${spec.name}"

    /** A service port's interfaces, published and subscribed as OpenRTM-aist's `CorbaPort` does. */
    private val service: ServiceInterfaces? =
        (spec as? PortSpec.Service)?.let { ServiceInterfaces(component.instanceName, it) }

    lateinit var ref: PortService
        private set

    fun activate(orb: RuntimeOrb) {
        ref = PortServiceHelper.narrow(orb.activate(this))
        service?.activate(orb)
    }

    fun deactivate(orb: RuntimeOrb) {
        publishers.values.forEach(Publisher::close)
        publishers.clear()
        inlets.values.forEach(orb::deactivate)
        inlets.clear()
        service?.deactivate(orb)
        orb.deactivate(this)
    }

    /** The latest sample received by this in-port, through any of its connectors. */
    fun latest(): Sample? = latestSample

    /**
     * Pushes [value] to every connected in-port, encoded once for each byte order its connectors negotiated, unless the
     * component's output is frozen or the type's IDL is not known.
     */
    fun write(value: Any) {
        val type = (spec as PortSpec.DataOut).dataType
        if (component.isOutputFrozen || !type.isEncodable || publishers.isEmpty()) return
        val time = System.currentTimeMillis() * 1_000_000
        val encoded = HashMap<Boolean, ByteArray>(2)
        for (publisher in publishers.values) {
            publisher.offer(
                encoded.getOrPut(publisher.littleEndian) { type.encode(value, time, publisher.littleEndian) }
            )
        }
        component.observers.raiseTraffic(fullName, outgoing = true)
    }

    override fun _invoke(method: String, input: InputStream, handler: ResponseHandler): OutputStream {
        component.gate.pass()
        return super._invoke(method, input, handler)
    }

    override fun get_port_profile(): PortProfile =
        PortProfile(
            fullName,
            interfaces(),
            ref,
            get_connector_profiles(),
            component.ref,
            properties().map { (name, value) -> component.nameValue(name, value) }.toTypedArray(),
        )

    override fun get_connector_profiles(): Array<ConnectorProfile> = connectors.values.toTypedArray()

    override fun get_connector_profile(connectorId: String): ConnectorProfile =
        connectors[connectorId] ?: ConnectorProfile("", "", emptyArray(), emptyArray())

    override fun connect(profile: ConnectorProfileHolder): ReturnCode_t {
        val ports = profile.value.ports
        if (ports.isEmpty()) return ReturnCode_t.BAD_PARAMETER
        val id = profile.value.connector_id
        if (id.isNullOrEmpty()) profile.value.connector_id = UUID.randomUUID().toString()
        else if (connectors.containsKey(id)) return ReturnCode_t.PRECONDITION_NOT_MET
        // As OutPortBase.connect and InPortBase.connect: offer both byte orders unless the caller chose.
        if (spec !is PortSpec.Service && profile.value.properties.none { it.name == ENDIAN }) {
            profile.value.properties += component.nameValue(ENDIAN, "little,big")
        }
        val code = ports[0].notify_connect(profile)
        // As PortBase.connect cleans up after a failed handshake; an id no port recorded is refused harmlessly.
        if (code != ReturnCode_t.RTC_OK) disconnect(profile.value.connector_id)
        return code
    }

    override fun notify_connect(profile: ConnectorProfileHolder): ReturnCode_t {
        val connector = profile.value
        val me = connector.ports.indexOfFirst { it._is_equivalent(ref) }
        if (me < 0 || connectors.containsKey(connector.connector_id)) return ReturnCode_t.BAD_PARAMETER
        val requested = connector.properties.associate { it.name to it.stringValue() }
        if (
            requested["dataport.allow_dup_connection"]?.uppercase() != "YES" &&
                connector.ports.any { !it._is_equivalent(ref) && connectedTo(it) }
        ) {
            return ReturnCode_t.PRECONDITION_NOT_MET
        }
        if (!accepts(requested)) return ReturnCode_t.BAD_PARAMETER
        val littleEndian =
            if (spec is PortSpec.Service) true else littleEndian(requested) ?: return ReturnCode_t.UNSUPPORTED

        if (spec is PortSpec.DataIn) {
            val inlet =
                InPortServant(spec.dataType, littleEndian) { sample ->
                    latestSample = sample
                    component.observers.raiseTraffic(fullName, outgoing = false)
                }
            inlet.ref = OpenRTM.InPortCdrHelper.narrow(component.orb.activate(inlet))
            inlets[connector.connector_id] = inlet
            connector.properties +=
                component.nameValue("dataport.corba_cdr.inport_ior", component.orb.orb.object_to_string(inlet.ref))
        }
        service?.let {
            connector.properties += it.published().map { (name, value) -> component.nameValue(name, value) }
        }
        if (me + 1 < connector.ports.size) {
            val next = connector.ports[me + 1].notify_connect(profile)
            if (next != ReturnCode_t.RTC_OK) {
                inlets.remove(connector.connector_id)?.let(component.orb::deactivate)
                return next
            }
        }
        val settled = profile.value
        // As PortBase.notify_connect: the connector is recorded even when subscribing failed, then the error answered.
        val subscribed = service?.subscribes(settled.properties.associate { it.name to it.stringValue() }) ?: true
        if (spec is PortSpec.DataOut) {
            val inPort =
                settled.properties.firstOrNull { it.name == "dataport.corba_cdr.inport_ior" }?.stringValue()
                    ?: return ReturnCode_t.BAD_PARAMETER
            publishers[settled.connector_id] =
                Publisher(
                    OpenRTM.InPortCdrHelper.narrow(component.orb.orb.string_to_object(inPort)),
                    component,
                    fullName,
                    littleEndian,
                )
        }
        connectors[settled.connector_id] = settled
        component.observers.raise(StatusKind.PORT_PROFILE, "CONNECT:$fullName")
        return if (subscribed) ReturnCode_t.RTC_OK else ReturnCode_t.RTC_ERROR
    }

    override fun disconnect(connectorId: String): ReturnCode_t {
        val connector = connectors[connectorId] ?: return ReturnCode_t.BAD_PARAMETER
        // As OpenRTM 1.1 does: the chain starts at the first port that answers, so a connector whose
        // first port died (a killed process) can still be removed from the live ones.
        for (port in connector.ports) {
            try {
                return port.notify_disconnect(connectorId)
            } catch (e: org.omg.CORBA.SystemException) {
                log.debug("{}: port of {} unreachable: {}", fullName, connectorId, e.toString())
            }
        }
        return ReturnCode_t.RTC_ERROR
    }

    override fun notify_disconnect(connectorId: String): ReturnCode_t {
        val connector = connectors.remove(connectorId) ?: return ReturnCode_t.BAD_PARAMETER
        publishers.remove(connectorId)?.close()
        inlets.remove(connectorId)?.let(component.orb::deactivate)
        component.observers.raise(StatusKind.PORT_PROFILE, "DISCONNECT:$fullName")
        val me = connector.ports.indexOfFirst { it._is_equivalent(ref) }
        if (me + 1 < connector.ports.size) {
            // The rest of the chain may be gone already (a dead peer); this side is disconnected anyway.
            runCatching { connector.ports[me + 1].notify_disconnect(connectorId) }
                .onFailure { log.debug("{}: next port of {} unreachable: {}", fullName, connectorId, it.toString()) }
        }
        return ReturnCode_t.RTC_OK
    }

    override fun disconnect_all(): ReturnCode_t {
        connectors.keys.toList().forEach(::disconnect)
        return ReturnCode_t.RTC_OK
    }

    /** Whether a connector of this port has [other] among its ports, as `CORBA_RTCUtil.already_connected` asks. */
    private fun connectedTo(other: PortService): Boolean =
        connectors.values.any { connector -> connector.ports.any { it._is_equivalent(other) } }

    private fun properties(): Map<String, String> =
        when (spec) {
            is PortSpec.DataIn -> dataPortProperties("DataInPort", spec.dataType)
            is PortSpec.DataOut -> dataPortProperties("DataOutPort", spec.dataType)
            is PortSpec.Service -> mapOf("port.port_type" to "CorbaPort")
        }

    private fun dataPortProperties(portType: String, dataType: DataType) =
        linkedMapOf(
            "port.port_type" to portType,
            "dataport.data_type" to dataType.repositoryId,
            "dataport.dataflow_type" to "push",
            "dataport.interface_type" to "corba_cdr",
            "dataport.subscription_type" to "flush,new,periodic",
        )

    /** Whether this port supports every connector property it advertises options for. */
    private fun accepts(requested: Map<String, String>): Boolean {
        val own = properties()
        val dataType = own["dataport.data_type"]
        val askedType = requested["dataport.data_type"]
        if (dataType != null && askedType != null && DataTypeName.repositoryId(askedType) != dataType) return false
        return listOf("dataport.dataflow_type", "dataport.interface_type", "dataport.subscription_type").all { key ->
            val asked = requested[key] ?: return@all true
            val offered = own[key] ?: return@all true
            asked.trim() in offered.split(',').map(String::trim)
        }
    }

    private fun interfaces(): Array<PortInterfaceProfile> =
        when (spec) {
            is PortSpec.Service ->
                spec.interfaces
                    .map { service ->
                        val polarity =
                            if (service.polarity == ServiceInterface.Polarity.PROVIDED) PortInterfacePolarity.PROVIDED
                            else PortInterfacePolarity.REQUIRED
                        PortInterfaceProfile(service.instanceName, service.typeName, polarity)
                    }
                    .toTypedArray()
            else -> emptyArray()
        }
}

private const val ENDIAN = "dataport.serializer.cdr.endian"

/**
 * The byte order a connector's `dataport.serializer.cdr.endian` chose, as OutPortBase.checkEndian reads it: its first
 * entry; little when the connector names no serializer at all (an old peer); null when the first entry is neither.
 */
private fun littleEndian(requested: Map<String, String>): Boolean? {
    if (requested.keys.none { it.startsWith("dataport.serializer") }) return true
    return when (requested[ENDIAN]?.split(',')?.firstOrNull()?.trim()?.lowercase()) {
        "little" -> true
        "big" -> false
        else -> null
    }
}

private operator fun Array<NameValue>.plus(value: NameValue): Array<NameValue> = (toList() + value).toTypedArray()
