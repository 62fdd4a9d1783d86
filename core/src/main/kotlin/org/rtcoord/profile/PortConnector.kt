package org.rtcoord.profile

import org.jspecify.annotations.Nullable

/**
 * A connection between two ports. Data port connectors carry the data-flow fields; service port
 * connectors [transMethod]. Connector properties (`dataport.*` and others) are in [ext]'s properties,
 * where rtshell and RTSystemEditor keep them.
 */
public data class PortConnector(
    val connectorId: String,
    val name: String,
    val source: TargetComponent,
    val target: TargetComponent,
    val dataType: @Nullable String? = null,
    val interfaceType: @Nullable String? = null,
    val dataflowType: @Nullable String? = null,
    val subscriptionType: @Nullable String? = null,
    val pushInterval: @Nullable Double? = null,
    val transMethod: @Nullable String? = null,
    val ext: Extension = Extension(),
) {
    /**
     * The properties to connect with: the profile's fields as `dataport.*` properties for a data
     * connector, overridden by the extension properties, without the object references rtshell leaves
     * out because they belong to the old connection.
     */
    public fun connectionProperties(): Map<String, String> = buildMap {
        dataflowType?.let { put("dataport.dataflow_type", it) }
        interfaceType?.let { put("dataport.interface_type", it) }
        subscriptionType?.let { put("dataport.subscription_type", it) }
        dataType?.let { put("dataport.data_type", it) }
        pushInterval?.let { put("dataport.push_interval", it.toString()) }
        putAll(ext.properties)
        keys.removeAll { it in STALE_REFERENCES || it == COMPONENT_PATH_ID }
    }

    internal companion object {
        /** The property rtshell stores the end's component path in. */
        const val COMPONENT_PATH_ID = "COMPONENT_PATH_ID"
        val STALE_REFERENCES = setOf(
            "dataport.corba_cdr.inport_ior", "dataport.corba_cdr.inport_ref",
            "dataport.corba_cdr.outport_ior", "dataport.corba_cdr.outport_ref",
        )
    }
}
