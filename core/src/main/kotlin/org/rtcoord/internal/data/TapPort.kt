package org.rtcoord.internal.data

import RTC.ConnectorProfile
import RTC.ConnectorProfileHolder
import RTC.PortProfile
import RTC.PortServicePOA
import RTC.ReturnCode_t
import _SDOPackage.NameValue
import org.omg.CORBA.ORB

/**
 * The in-port side of a tap's connector, as rtshell and other tools see it: a `PortService` named [name], without an
 * owning component, that takes part in the out-port's connect and disconnect chain (OpenRTM's `notify_connect` and
 * `notify_disconnect`) and holds the connector while it exists. The data itself goes to the tap's `InPortCdr`. Tools
 * cannot connect it to anything else.
 */
internal class TapPort(private val orb: ORB, private val name: String, private val dataType: String) :
    PortServicePOA() {
    @Volatile private var connector: ConnectorProfile? = null

    /** This port's reference, set once it is served. */
    lateinit var reference: RTC.PortService

    override fun get_port_profile(): PortProfile =
        PortProfile(
            name,
            emptyArray(),
            reference,
            get_connector_profiles(),
            null,
            mapOf(
                    "port.port_type" to "DataInPort",
                    "dataport.data_type" to dataType,
                    "dataport.dataflow_type" to "push",
                    "dataport.interface_type" to "corba_cdr",
                )
                .map { (key, value) -> NameValue(key, orb.create_any().apply { insert_string(value) }) }
                .toTypedArray(),
        )

    override fun get_connector_profiles(): Array<ConnectorProfile> = listOfNotNull(connector).toTypedArray()

    override fun get_connector_profile(connectorId: String): ConnectorProfile =
        connector?.takeIf { it.connector_id == connectorId } ?: ConnectorProfile("", "", emptyArray(), emptyArray())

    override fun connect(profile: ConnectorProfileHolder): ReturnCode_t = ReturnCode_t.UNSUPPORTED

    override fun notify_connect(profile: ConnectorProfileHolder): ReturnCode_t {
        if (connector != null) return ReturnCode_t.PRECONDITION_NOT_MET
        connector = profile.value
        return ReturnCode_t.RTC_OK
    }

    override fun disconnect(connectorId: String): ReturnCode_t = ReturnCode_t.UNSUPPORTED

    override fun notify_disconnect(connectorId: String): ReturnCode_t {
        if (connector?.connector_id != connectorId) return ReturnCode_t.BAD_PARAMETER
        connector = null
        return ReturnCode_t.RTC_OK
    }

    override fun disconnect_all(): ReturnCode_t = ReturnCode_t.UNSUPPORTED
}
