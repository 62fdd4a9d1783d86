package org.rtcoord.profile

import org.jspecify.annotations.Nullable
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields
import org.rtcoord.profile.internal.COMPONENT_PATH_ID
import org.rtcoord.profile.internal.withoutReferences

/**
 * A connection between two ports. Data port connectors carry the data-flow fields; service port connectors
 * [transMethod]. Connector properties (`dataport.*` and others) are in [ext]'s properties, where rtshell and
 * RTSystemEditor keep them.
 */
public class PortConnector
@JvmOverloads
constructor(
    public val connectorId: String,
    public val name: String,
    public val source: TargetComponent,
    public val target: TargetComponent,
    public val dataType: @Nullable String? = null,
    public val interfaceType: @Nullable String? = null,
    public val dataflowType: @Nullable String? = null,
    public val subscriptionType: @Nullable String? = null,
    public val pushInterval: @Nullable Double? = null,
    public val transMethod: @Nullable String? = null,
    public val ext: Extension = Extension(),
) : ValueObject() {
    /**
     * The properties to connect with: the profile's fields as `dataport.*` properties for a data connector, overridden
     * by the extension properties, without the object references that belong to the old connection: those rtshell
     * leaves out and every value that is an IOR, such as the `port.<type>.<instance>` a service port publishes for each
     * interface it provides.
     */
    public fun connectionProperties(): Map<String, String> = buildMap {
        dataflowType?.let { put("dataport.dataflow_type", it) }
        interfaceType?.let { put("dataport.interface_type", it) }
        subscriptionType?.let { put("dataport.subscription_type", it) }
        dataType?.let { put("dataport.data_type", it) }
        pushInterval?.let { put("dataport.push_interval", it.toString()) }
        putAll(withoutReferences(ext.properties))
        remove(COMPONENT_PATH_ID)
    }

    /** This connector with another [connectorId] (empty: one the ports choose when connected). */
    public fun withConnectorId(connectorId: String): PortConnector = copy(connectorId = connectorId)

    /** This connector from another [source] port. */
    public fun withSource(source: TargetComponent): PortConnector = copy(source = source)

    /** This connector with another [subscriptionType] (`flush`, `new`, `periodic`), or none. */
    public fun withSubscriptionType(subscriptionType: @Nullable String?): PortConnector =
        copy(subscriptionType = subscriptionType)

    /** This connector with another [ext]. */
    public fun withExt(ext: Extension): PortConnector = copy(ext = ext)

    private fun copy(
        connectorId: String = this.connectorId,
        source: TargetComponent = this.source,
        subscriptionType: String? = this.subscriptionType,
        ext: Extension = this.ext,
    ) =
        PortConnector(
            connectorId,
            name,
            source,
            target,
            dataType,
            interfaceType,
            dataflowType,
            subscriptionType,
            pushInterval,
            transMethod,
            ext,
        )

    override fun fields(): ValueFields =
        ValueFields(
            "connectorId" to connectorId,
            "name" to name,
            "source" to source,
            "target" to target,
            "dataType" to dataType,
            "interfaceType" to interfaceType,
            "dataflowType" to dataflowType,
            "subscriptionType" to subscriptionType,
            "pushInterval" to pushInterval,
            "transMethod" to transMethod,
            "ext" to ext,
        )
}
