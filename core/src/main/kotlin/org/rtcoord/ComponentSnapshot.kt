package org.rtcoord

import org.rtcoord.internal.FSM_SERVICE_ID
import org.rtcoord.internal.ValueFields

/**
 * What was read from a component at one moment: profile, ports with their connectors, execution contexts with the
 * component's state in each, and configuration once it was asked for ([ComponentNode.configuration]). Immutable; a
 * refresh publishes a new one.
 */
public class ComponentSnapshot(
    public val instanceName: String,
    public val typeName: String,
    public val description: String,
    public val version: String,
    public val vendor: String,
    public val category: String,
    /** The instance name of the profile's parent object; null when it has none (OpenRTM-aist never sets one). */
    public val parent: String?,
    public val properties: Map<String, String>,
    public val ports: List<PortSnapshot>,
    public val contexts: List<ContextSnapshot>,
    /** Null until the configuration was first read; kept up to date by every refresh after that. */
    public val configuration: ConfigurationSnapshot?,
) : ValueObject() {
    /** The state in the execution context with handle 0 (the first owned one), as tools show it. */
    public val state: LifeCycle
        get() = context(0)?.state ?: contexts.firstOrNull()?.state ?: LifeCycle.UNKNOWN

    /** The state over all its execution contexts (see [ComponentSummary.overallState]). */
    public val overallState: LifeCycle
        get() = summary.overallState

    /** The execution context with [handle], or null. */
    public fun context(handle: Int): ContextSnapshot? = contexts.firstOrNull { it.handle == handle }

    /**
     * Whether it offers FSM4RTC's `ExtendedFsmService` (in `sdo.service.provider.available_services`), as an FSM
     * component of OpenRTM-aist 2.0 does when the service's module is loaded; see [SystemSnapshot]'s
     * [ComponentEntry.fsm] for its state.
     */
    public val offersFsmService: Boolean
        get() =
            properties["sdo.service.provider.available_services"].orEmpty().split(',').any {
                it.trim() == FSM_SERVICE_ID
            }

    /** The port named [name] (without the instance prefix), or null. */
    public fun port(name: String): PortSnapshot? = ports.firstOrNull { it.name == name }

    /** This snapshot with other [contexts] or [configuration], as the tree re-reads them. */
    @JvmSynthetic
    internal fun copy(
        contexts: List<ContextSnapshot> = this.contexts,
        configuration: ConfigurationSnapshot? = this.configuration,
    ): ComponentSnapshot =
        ComponentSnapshot(
            instanceName,
            typeName,
            description,
            version,
            vendor,
            category,
            parent,
            properties,
            ports,
            contexts,
            configuration,
        )

    /**
     * This snapshot with each context in the state [stateOf] gives it (null: as it is), asked once per context; this
     * very snapshot when no state changes, as nearly every read of the states finds.
     */
    @JvmSynthetic
    internal fun withStates(stateOf: (ContextSnapshot) -> LifeCycle?): ComponentSnapshot {
        var changed = false
        val updated = contexts.map { context ->
            val state = stateOf(context)
            if (state == null || state == context.state) context
            else context.copy(state = state).also { changed = true }
        }
        return if (changed) copy(contexts = updated) else this
    }

    override fun fields(): ValueFields =
        ValueFields(
            "instanceName" to instanceName,
            "typeName" to typeName,
            "description" to description,
            "version" to version,
            "vendor" to vendor,
            "category" to category,
            "parent" to parent,
            "properties" to properties,
            "ports" to ports,
            "contexts" to contexts,
            "configuration" to configuration,
        )
}

/** The kind of a port, from its `port.port_type` property. */
public enum class PortKind {
    DATA_IN,
    DATA_OUT,
    SERVICE,
    OTHER,
}

/**
 * A port: its short [name], OpenRTM's [fullName] (`instance.port`), kind, data type for data ports, the interfaces a
 * service port provides and requires, advertised properties and current connectors.
 */
public class PortSnapshot(
    public val name: String,
    public val fullName: String,
    public val kind: PortKind,
    public val dataType: String?,
    /** The service interfaces, in the order the component registered them; none for data ports. */
    public val interfaces: List<PortInterface>,
    public val properties: Map<String, String>,
    public val connectors: List<ConnectorSnapshot>,
) : ValueObject() {
    override fun fields(): ValueFields =
        ValueFields(
            "name" to name,
            "fullName" to fullName,
            "kind" to kind,
            "dataType" to dataType,
            "interfaces" to interfaces,
            "properties" to properties,
            "connectors" to connectors,
        )
}

/** A service interface of a port, from its `PortInterfaceProfile`: [instanceName] of IDL type [typeName]. */
public class PortInterface(
    public val instanceName: String,
    public val typeName: String,
    public val polarity: Polarity,
) : ValueObject() {
    /** Whether the port provides the interface (serves it) or requires it (calls one provided elsewhere). */
    public enum class Polarity {
        PROVIDED,
        REQUIRED,
    }

    override fun fields(): ValueFields =
        ValueFields("instanceName" to instanceName, "typeName" to typeName, "polarity" to polarity)
}

/** A connection as one of its ports records it; [Port.connections] resolves its ends to tree paths. */
public class ConnectorSnapshot(
    public val id: String,
    public val name: String,
    public val properties: Map<String, String>,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("id" to id, "name" to name, "properties" to properties)
}

/** An execution context as seen from one component. */
public class ContextSnapshot(
    /** The component's handle for it: owned contexts 0.., participating ones from 1000. */
    public val handle: Int,
    @get:JvmName("isOwned") public val owned: Boolean,
    public val kind: String,
    public val rate: Double,
    @get:JvmName("isRunning") public val running: Boolean,
    /** The component's state in this context. */
    public val state: LifeCycle,
    /** How many components take part in it. */
    public val participants: Int,
    /**
     * The context's profile properties: OpenRTM-aist puts there the options it was created with (`type`, `rate` as
     * configured, `sync_transition`, `transition_timeout`...); empty for a context without a profile.
     */
    public val properties: Map<String, String>,
) : ValueObject() {
    /** This context as seen with another [state] (or [handle]). */
    @JvmSynthetic
    internal fun copy(handle: Int = this.handle, state: LifeCycle = this.state): ContextSnapshot =
        ContextSnapshot(handle, owned, kind, rate, running, state, participants, properties)

    override fun fields(): ValueFields =
        ValueFields(
            "handle" to handle,
            "owned" to owned,
            "kind" to kind,
            "rate" to rate,
            "running" to running,
            "state" to state,
            "participants" to participants,
            "properties" to properties,
        )
}

/**
 * Configuration sets by id (hidden `__name__` sets included) and which one is active: null when none is, as
 * OpenRTM-aist leaves a component after a set was written, added or removed until one is activated.
 */
public class ConfigurationSnapshot(public val sets: Map<String, Map<String, String>>, public val activeSet: String?) :
    ValueObject() {
    /** The value of [parameter] in the active set, or null (also when no set is active). */
    public fun value(parameter: String): String? = activeSet?.let { sets[it]?.get(parameter) }

    override fun fields(): ValueFields = ValueFields("sets" to sets, "activeSet" to activeSet)
}
