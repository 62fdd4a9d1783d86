package org.rtcoord.runtime

/**
 * What a factory creates: a component type with its ports, configuration parameters, behaviour and execution context. A
 * manager creates instances of the types its loaded modules provide.
 */
public class ComponentType(
    public val typeName: String,
    public val ports: List<PortSpec> = emptyList(),
    public val parameters: List<ParameterSpec> = emptyList(),
    /**
     * Extra configuration sets besides `default`, by id, each with the values it holds (activated, it sets only those).
     */
    public val configurationSets: Map<String, Map<String, String>> = emptyMap(),
    public val behaviour: () -> Behaviour = { Behaviour.Idle },
    /** The owned periodic execution context's rate in Hz, unless [contexts] says otherwise. */
    rate: Double = 100.0,
    /** The observer flavours instances accept (both by default, like a component with fsm4rtc preloaded). */
    public val observerFlavours: Set<ObserverFlavour> = ObserverFlavour.values().toSet(),
    public val vendor: String = "rtcoord",
    public val category: String = "fixture",
    public val version: String = "1.0.0",
    public val description: String = "rtcoord fixture component $typeName",
    /**
     * The state machine of an FSM component (OpenRTM-aist 2.0's StaticFSM), which then offers `ExtendedFsmService`;
     * null for others.
     */
    public val fsm: FsmSpec? = null,
    /**
     * The execution contexts instances own, handles 0, 1, ... in this order: by default one periodic context at [rate].
     */
    public val contexts: List<ContextSpec> = listOf(ContextSpec(rate)),
) {
    /** The rate of the first owned context, in Hz. */
    public val rate: Double
        get() = contexts.first().rate

    init {
        require(typeName.isNotBlank()) { "a component type needs a name" }
        require(contexts.isNotEmpty()) { "$typeName owns no execution context" }
        val duplicate = ports.groupBy { it.name }.filterValues { it.size > 1 }.keys
        require(duplicate.isEmpty()) { "$typeName declares ports $duplicate twice" }
    }

    /** A copy of this type that accepts only the observer [flavours] (none: polling only). */
    public fun acceptingObservers(vararg flavours: ObserverFlavour): ComponentType =
        ComponentType(
            typeName,
            ports,
            parameters,
            configurationSets,
            behaviour,
            rate,
            flavours.toSet(),
            vendor,
            category,
            version,
            description,
            fsm,
            contexts,
        )
}

/** A port of a component type. */
public sealed class PortSpec(public val name: String) {
    /** A data in-port receiving [dataType] over `corba_cdr` push connections. */
    public class DataIn(name: String, public val dataType: DataType) : PortSpec(name)

    /** A data out-port sending [dataType]. */
    public class DataOut(name: String, public val dataType: DataType) : PortSpec(name)

    /**
     * A service port (OpenRTM-aist's `CorbaPort`) with its [interfaces] in the order the component registered them. A
     * provided interface has no implementation: a call on it is answered with `NO_IMPLEMENT`
     * ([NoImplementationServant]).
     */
    public class Service(name: String, public val interfaces: List<ServiceInterface>) : PortSpec(name) {
        /**
         * A port providing the [provided] interfaces then requiring the [required] ones (`instance name` to `type`).
         */
        @JvmOverloads
        public constructor(
            name: String,
            provided: Map<String, String> = emptyMap(),
            required: Map<String, String> = emptyMap(),
        ) : this(
            name,
            provided.map { (instance, type) -> ServiceInterface(instance, type, ServiceInterface.Polarity.PROVIDED) } +
                required.map { (instance, type) ->
                    ServiceInterface(instance, type, ServiceInterface.Polarity.REQUIRED)
                },
        )

        init {
            val twice = interfaces.groupBy { it.polarity to it.instanceName }.filterValues { it.size > 1 }.keys
            require(twice.isEmpty()) {
                "service port $name registers ${twice.joinToString { "${it.first.name.lowercase()} ${it.second}" }} twice"
            }
        }
    }
}

/**
 * An interface of a service port: [instanceName] of IDL type [typeName] (`SimpleService::MyService`), provided or
 * required.
 */
public class ServiceInterface(
    public val instanceName: String,
    public val typeName: String,
    public val polarity: Polarity,
) {
    /** `RTC::PortInterfacePolarity`. */
    public enum class Polarity {
        PROVIDED,
        REQUIRED,
    }

    /** OpenRTM-aist's descriptor of it in connector properties: `<type>.<instance>`. */
    public val descriptor: String
        get() = "$typeName.$instanceName"

    override fun toString(): String = "${polarity.name.lowercase()} $instanceName ($typeName)"
}

/** A configuration parameter: its name, default value and the check a new value must pass. */
public class ParameterSpec(
    public val name: String,
    public val default: String,
    public val accepts: (String) -> Boolean = { true },
) {
    init {
        require(accepts(default)) { "parameter $name rejects its own default '$default'" }
    }

    public companion object {
        /** A parameter holding a decimal number. */
        public fun decimal(name: String, default: Double): ParameterSpec =
            ParameterSpec(name, default.toString()) { it.trim().toDoubleOrNull() != null }

        /** A parameter holding a whole number. */
        public fun integer(name: String, default: Int): ParameterSpec =
            ParameterSpec(name, default.toString()) { it.trim().toIntOrNull() != null }
    }
}
