package org.rtcoord.profile

import org.jspecify.annotations.Nullable

/**
 * An RTSProfile 0.2 document: a whole RT system as RTSystemEditor and rtshell save it. Read and write it
 * with [RtsProfiles]; save, restore, check and order a live system with [SystemProfiles].
 *
 * Every element keeps its `rts_ext` data and whatever the schema does not name in its [Extension], so
 * reading and writing a file loses nothing.
 */
public data class RtsProfile(
    /** `RTSystem:vendor:name:version`. */
    val id: String,
    val version: String = "0.2",
    val abstract: String = "",
    /** `YYYY-MM-DDTHH:MM:SS`, as rtshell writes it. */
    val creationDate: String = "",
    val updateDate: String = "",
    val components: List<ProfileComponent> = emptyList(),
    val groups: List<ComponentGroup> = emptyList(),
    val dataPortConnectors: List<PortConnector> = emptyList(),
    val servicePortConnectors: List<PortConnector> = emptyList(),
    /** The ordering blocks by kind; a kind the file does not have is absent. */
    val orderings: Map<OrderingKind, Ordering> = emptyMap(),
    val ext: Extension = Extension(),
) {
    /** The component [target] names: by instance name and component id, as rtshell finds it. */
    public fun component(target: TargetComponent): @Nullable ProfileComponent? =
        components.firstOrNull { it.instanceName == target.instanceName && it.id == target.componentId }
            ?: components.firstOrNull { it.instanceName == target.instanceName }
}

/** A component group (`Groups`): an id and its members. */
public data class ComponentGroup(val groupId: String, val members: List<TargetComponent> = emptyList(), val ext: Extension = Extension())
