package org.rtcoord.runtime

/**
 * What a service port does with its interfaces when it connects, as OpenRTM-aist's `CorbaPort` (`publishInterfaces`,
 * `subscribeInterfaces`): each provided interface is published in the connector's properties under two names,
 * `<instance>.port.<port>.provided.<type>.<name>` and the older `port.<type>.<name>`, whose value is the IOR of an
 * object answering `NO_IMPLEMENT` ([NoImplementationServant]); each required interface looks for its provider, first
 * through `<instance>.port.<port>.required.<type>.<name>` (whose value names a provider's property), then through
 * `port.<type>.<name>`. A required interface with no provider is no error unless the connector asks for
 * `port.connection.strictness` `strict`; what a found provider's value holds is not checked, as `CorbaPort` ignores
 * whether its consumer could use it.
 */
internal class ServiceInterfaces(instanceName: String, private val spec: PortSpec.Service) {
    /** `<instance>.port.<port>`: the prefix of the port's new-style descriptors. */
    private val prefix = "$instanceName.port.${spec.name}"
    private val providers =
        spec.interfaces
            .filter { it.polarity == ServiceInterface.Polarity.PROVIDED }
            .map { it to NoImplementationServant("$instanceName.${spec.name}", it) }
    private val required = spec.interfaces.filter { it.polarity == ServiceInterface.Polarity.REQUIRED }
    private var references: List<Pair<ServiceInterface, String>> = emptyList()

    fun activate(orb: RuntimeOrb) {
        references = providers.map { (service, servant) -> service to orb.orb.object_to_string(orb.activate(servant)) }
    }

    fun deactivate(orb: RuntimeOrb) = providers.forEach { (_, servant) -> orb.deactivate(servant) }

    /** The properties this port adds to a connector: each provided interface's IOR, under both names. */
    fun published(): List<Pair<String, String>> = references.flatMap { (service, ior) ->
        listOf("$prefix.provided.${service.descriptor}" to ior, "port.${service.descriptor}" to ior)
    }

    /** Whether every required interface finds its provider in [properties], or the connector does not insist. */
    fun subscribes(properties: Map<String, String>): Boolean {
        if (properties["port.connection.strictness"] != "strict") return true
        return required.all { service -> !providerOf(service, properties).isNullOrEmpty() }
    }

    private fun providerOf(service: ServiceInterface, properties: Map<String, String>): String? =
        properties["$prefix.required.${service.descriptor}"]?.let { properties[it] }
            ?: properties["port.${service.descriptor}"]
}
