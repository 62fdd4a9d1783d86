package org.rtcoord.profile

import org.jspecify.annotations.Nullable
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/**
 * An RTSProfile 0.2 document: a whole RT system as RTSystemEditor and rtshell save it. Read and write it with
 * [RtsProfiles]; save, restore, check and order a live system with [SystemProfiles]; change it with the `with...`
 * methods, each of which returns a changed copy.
 *
 * Every element keeps its `rts_ext` data and whatever the schema does not name in its [Extension], so reading and
 * writing a file loses nothing.
 */
public class RtsProfile
@JvmOverloads
constructor(
    /** `RTSystem:vendor:name:version`. */
    public val id: String,
    public val version: String = "0.2",
    public val abstract: String = "",
    /** `YYYY-MM-DDTHH:MM:SS`, as rtshell writes it. */
    public val creationDate: String = "",
    public val updateDate: String = "",
    public val components: List<ProfileComponent> = emptyList(),
    public val groups: List<ComponentGroup> = emptyList(),
    public val dataPortConnectors: List<PortConnector> = emptyList(),
    public val servicePortConnectors: List<PortConnector> = emptyList(),
    /** The ordering blocks by kind; a kind the file does not have is absent. */
    public val orderings: Map<OrderingKind, Ordering> = emptyMap(),
    public val ext: Extension = Extension(),
) : ValueObject() {
    /** The component [target] names: by instance name and component id, as rtshell finds it. */
    public fun component(target: TargetComponent): @Nullable ProfileComponent? =
        components.firstOrNull { it.instanceName == target.instanceName && it.id == target.componentId }
            ?: components.firstOrNull { it.instanceName == target.instanceName }

    /** This profile with [components] instead of its own. */
    public fun withComponents(components: List<ProfileComponent>): RtsProfile = copy(components = components)

    /** This profile with [connectors] as its data port connectors. */
    public fun withDataPortConnectors(connectors: List<PortConnector>): RtsProfile =
        copy(dataPortConnectors = connectors)

    /** This profile with [connectors] as its service port connectors. */
    public fun withServicePortConnectors(connectors: List<PortConnector>): RtsProfile =
        copy(servicePortConnectors = connectors)

    /** This profile with [orderings] instead of its own ordering blocks. */
    public fun withOrderings(orderings: Map<OrderingKind, Ordering>): RtsProfile = copy(orderings = orderings)

    /** This profile with another [ext]. */
    public fun withExt(ext: Extension): RtsProfile = copy(ext = ext)

    private fun copy(
        components: List<ProfileComponent> = this.components,
        dataPortConnectors: List<PortConnector> = this.dataPortConnectors,
        servicePortConnectors: List<PortConnector> = this.servicePortConnectors,
        orderings: Map<OrderingKind, Ordering> = this.orderings,
        ext: Extension = this.ext,
    ) =
        RtsProfile(
            id,
            version,
            abstract,
            creationDate,
            updateDate,
            components,
            groups,
            dataPortConnectors,
            servicePortConnectors,
            orderings,
            ext,
        )

    override fun fields(): ValueFields =
        ValueFields(
            "id" to id,
            "version" to version,
            "abstract" to abstract,
            "creationDate" to creationDate,
            "updateDate" to updateDate,
            "components" to components,
            "groups" to groups,
            "dataPortConnectors" to dataPortConnectors,
            "servicePortConnectors" to servicePortConnectors,
            "orderings" to orderings,
            "ext" to ext,
        )
}

/** A component group (`Groups`): an id and its members. */
public class ComponentGroup
@JvmOverloads
constructor(
    public val groupId: String,
    public val members: List<TargetComponent> = emptyList(),
    public val ext: Extension = Extension(),
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("groupId" to groupId, "members" to members, "ext" to ext)
}
