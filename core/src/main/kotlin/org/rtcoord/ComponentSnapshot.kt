package org.rtcoord

/**
 * What was read from a component at one moment: profile, ports with their connectors, execution
 * contexts with the component's state in each, and configuration once it was asked for
 * ([ComponentNode.configuration]). Immutable; a refresh publishes a new one.
 */
public data class ComponentSnapshot(
    val instanceName: String,
    val typeName: String,
    val description: String,
    val version: String,
    val vendor: String,
    val category: String,
    /** The instance name of the profile's parent object; null when it has none (OpenRTM-aist never sets one). */
    val parent: String?,
    val properties: Map<String, String>,
    val ports: List<PortSnapshot>,
    val contexts: List<ContextSnapshot>,
    /** Null until the configuration was first read; kept up to date by every refresh after that. */
    val configuration: ConfigurationSnapshot?,
) {
    /** The state in the execution context with handle 0 (the first owned one), as tools show it. */
    val state: LifeCycle get() = context(0)?.state ?: contexts.firstOrNull()?.state ?: LifeCycle.UNKNOWN

    /** The state over all its execution contexts (see [ComponentSummary.overallState]). */
    val overallState: LifeCycle get() = summary.overallState

    /** The execution context with [handle], or null. */
    public fun context(handle: Int): ContextSnapshot? = contexts.firstOrNull { it.handle == handle }

    /** The port named [name] (without the instance prefix), or null. */
    public fun port(name: String): PortSnapshot? = ports.firstOrNull { it.name == name }
}

/** The kind of a port, from its `port.port_type` property. */
public enum class PortKind { DATA_IN, DATA_OUT, SERVICE, OTHER }

/**
 * A port: its short [name], OpenRTM's [fullName] (`instance.port`), kind, data type for data ports,
 * the interfaces a service port provides and requires, advertised properties and current connectors.
 */
public data class PortSnapshot(
    val name: String,
    val fullName: String,
    val kind: PortKind,
    val dataType: String?,
    /** The service interfaces, in the order the component registered them; none for data ports. */
    val interfaces: List<PortInterface>,
    val properties: Map<String, String>,
    val connectors: List<ConnectorSnapshot>,
)

/** A service interface of a port, from its `PortInterfaceProfile`: [instanceName] of IDL type [typeName]. */
public data class PortInterface(val instanceName: String, val typeName: String, val polarity: Polarity) {
    /** Whether the port provides the interface (serves it) or requires it (calls one provided elsewhere). */
    public enum class Polarity { PROVIDED, REQUIRED }
}

/** A connection as one of its ports records it; [Port.connections] resolves its ends to tree paths. */
public data class ConnectorSnapshot(
    val id: String,
    val name: String,
    val properties: Map<String, String>,
)

/** An execution context as seen from one component. */
public data class ContextSnapshot(
    /** The component's handle for it: owned contexts 0.., participating ones from 1000. */
    val handle: Int,
    @get:JvmName("isOwned") val owned: Boolean,
    val kind: String,
    val rate: Double,
    @get:JvmName("isRunning") val running: Boolean,
    /** The component's state in this context. */
    val state: LifeCycle,
    /** How many components take part in it. */
    val participants: Int,
    /**
     * The context's profile properties: OpenRTM-aist puts there the options it was created with
     * (`type`, `rate` as configured, `sync_transition`, `transition_timeout`...); empty for a context
     * without a profile.
     */
    val properties: Map<String, String>,
)

/**
 * Configuration sets by id (hidden `__name__` sets included) and which one is active: null when none is,
 * as OpenRTM-aist leaves a component after a set was written, added or removed until one is activated.
 */
public data class ConfigurationSnapshot(val sets: Map<String, Map<String, String>>, val activeSet: String?) {
    /** The value of [parameter] in the active set, or null (also when no set is active). */
    public fun value(parameter: String): String? = activeSet?.let { sets[it]?.get(parameter) }

    internal companion object {
        val NONE = ConfigurationSnapshot(emptyMap(), null)
    }
}
