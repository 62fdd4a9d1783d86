package org.rtcoord.internal

import RTC.ComponentProfile
import RTC.ExecutionContext
import RTC.ExecutionContextServiceHelper
import RTC.LifeCycleState
import RTC.PortService
import RTC.RTObject
import _SDOPackage.Configuration
import _SDOPackage.NameValue
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.ComponentSnapshot
import org.rtcoord.ComponentSummary
import org.rtcoord.Composition
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.ConnectorSnapshot
import org.rtcoord.ContextSnapshot
import org.rtcoord.OperationUnsupportedException
import org.rtcoord.PortInterface
import org.rtcoord.PortKind
import org.rtcoord.PortSnapshot

/**
 * Reads a component, issuing the independent remote calls concurrently: profile, ports and execution contexts together
 * ([read]), configuration apart ([readConfiguration]), since listing a system does not need it and every call counts at
 * a thousand components; for listings, only what they show ([readSummary]).
 */
internal class ComponentReader(private val remote: Remote, private val subject: String, private val ref: RTObject) {

    /** A snapshot and the references behind it. */
    class Reading(
        val snapshot: ComponentSnapshot,
        val contexts: Map<Int, ExecutionContext>,
        val ports: Map<String, PortService>,
    )

    /** A summary and the instance name the profile read for it gave. */
    class SummaryReading(val summary: ComponentSummary, val instanceName: String)

    suspend fun read(): Reading = coroutineScope {
        val profile = async { readProfile() }
        val contexts = async {
            readContexts()
                .map { (context, isOwned, handle) -> async { readContext(context, isOwned, handle) } }
                .awaitAll()
        }
        val p = profile.await()
        // OpenRTM-aist never sets a parent: the extra call is made only for a component that has one.
        val parent =
            p.parent?.let { parent ->
                remote
                    .call(subject, "get_component_profile of the parent") { parent.get_component_profile() }
                    .instance_name
            }
        val read = contexts.await()
        val snapshot =
            ComponentSnapshot(
                instanceName = p.instance_name,
                typeName = p.type_name.shared(),
                description = p.description.shared(),
                version = p.version.shared(),
                vendor = p.vendor.shared(),
                category = p.category.shared(),
                parent = parent,
                properties = p.properties.toMap(),
                ports = portsOf(p),
                contexts = read.map { it.first },
                configuration = null,
            )
        Reading(
            snapshot,
            read.map { it.first.handle to it.second }.toMap(),
            portReferences(p),
        )
    }

    /** The component's port references by short port name, read now. */
    suspend fun readPorts(): Map<String, PortService> = portReferences(readProfile())

    private fun portReferences(p: ComponentProfile): Map<String, PortService> =
        p.port_profiles.associate { it.name.removePrefix("${p.instance_name}.") to it.port_ref }

    /** What a listing shows: the profile's ports and the state in each context, without the contexts' own details. */
    suspend fun readSummary(): SummaryReading = coroutineScope {
        val profile = async { readProfile() }
        val states = async {
            readContexts()
                .map { (context, _, handle) -> async { handle to readState(context).toLifeCycle() } }
                .awaitAll()
                .toMap()
        }
        val p = profile.await()
        SummaryReading(ComponentSummary(states.await(), portsOf(p)), p.instance_name)
    }

    private suspend fun readProfile(): ComponentProfile =
        remote.call(subject, "get_component_profile") { ref.get_component_profile() }

    /** Every context with whether the component owns it and its handle for it. */
    private suspend fun readContexts(): List<Triple<ExecutionContext, Boolean, Int>> = coroutineScope {
        val owned = async { remote.call(subject, "get_owned_contexts") { ref.get_owned_contexts() } }
        val participating = async {
            remote.call(subject, "get_participating_contexts") { ref.get_participating_contexts() }
        }
        // OpenRTM numbers owned contexts 0.. and participating ones 1000.. in list order.
        owned.await().mapIndexed { index, context -> Triple(context, true, index) } +
            participating.await().mapIndexed { index, context -> Triple(context, false, PARTICIPATING_BASE + index) }
    }

    private suspend fun readState(context: ExecutionContext): LifeCycleState =
        remote.call(subject, "get_component_state") { context.get_component_state(ref) }

    private fun portsOf(p: ComponentProfile): List<PortSnapshot> =
        p.port_profiles.map { port ->
            val properties = port.properties.toMap(valuesRepeat = true)
            PortSnapshot(
                name = port.name.removePrefix("${p.instance_name}.").shared(),
                fullName = port.name,
                kind =
                    when (properties["port.port_type"]) {
                        "DataInPort" -> PortKind.DATA_IN
                        "DataOutPort" -> PortKind.DATA_OUT
                        "CorbaPort" -> PortKind.SERVICE
                        else -> PortKind.OTHER
                    },
                dataType = properties["dataport.data_type"],
                interfaces =
                    port.interfaces.map { profile ->
                        val polarity =
                            if (profile.polarity == RTC.PortInterfacePolarity.PROVIDED) PortInterface.Polarity.PROVIDED
                            else PortInterface.Polarity.REQUIRED
                        PortInterface(profile.instance_name.shared(), profile.type_name.shared(), polarity)
                    },
                properties = properties,
                connectors =
                    port.connector_profiles.map { connector ->
                        ConnectorSnapshot(connector.connector_id, connector.name, connector.properties.toMap())
                    },
            )
        }

    private suspend fun readContext(
        context: ExecutionContext,
        owned: Boolean,
        handle: Int,
    ): Pair<ContextSnapshot, ExecutionContext> = coroutineScope {
        val state = async { readState(context) }
        val running = async { remote.call(subject, "is_running") { context.is_running() } }
        val profile = async {
            // Plain ExecutionContexts have no profile: fall back to what every context answers.
            try {
                remote
                    .call(subject, "get_profile") {
                        ExecutionContextServiceHelper.unchecked_narrow(context).get_profile()
                    }
                    .let { ContextProfile(it.kind.label(), it.rate, it.participants.size, it.properties.toMap()) }
            } catch (e: OperationUnsupportedException) {
                ContextProfile(
                    remote.call(subject, "get_kind") { context.get_kind() }.label(),
                    remote.call(subject, "get_rate") { context.get_rate() },
                    0,
                    emptyMap(),
                )
            }
        }
        val (kind, rate, participants, properties) = profile.await()
        ContextSnapshot(
            handle,
            owned,
            kind,
            rate,
            running.await(),
            state.await().toLifeCycle(),
            participants,
            properties,
        ) to context
    }

    /** What a context's profile says of it, or what a plain context answers in its place. */
    private data class ContextProfile(
        val kind: String,
        val rate: Double,
        val participants: Int,
        val properties: Map<String, String>,
    )

    /**
     * Whether the component owns SDO organisations (a composite) and belongs to any (a member), as rtctree reads it.
     */
    suspend fun readComposition(): Composition = coroutineScope {
        val owned = async { remote.call(subject, "get_owned_organizations") { ref.get_owned_organizations() } }
        val memberOf = async { remote.call(subject, "get_organizations") { ref.get_organizations() } }
        Composition(isComposite = owned.await().isNotEmpty(), isMember = memberOf.await().isNotEmpty())
    }

    /** The configuration sets, through [configuration] (the component's, fetched when null). */
    suspend fun readConfiguration(configuration: Configuration?): Pair<ConfigurationSnapshot, Configuration?> {
        val target =
            configuration
                ?: try {
                    remote.call(subject, "get_configuration") { ref.get_configuration() }
                } catch (e: OperationUnsupportedException) {
                    return ConfigurationSnapshot(emptyMap(), null) to null
                }
        return readSets(target) to target
    }

    private suspend fun readSets(configuration: Configuration): ConfigurationSnapshot {
        return coroutineScope {
            val sets = async {
                remote.call(subject, "get_configuration_sets") { configuration.get_configuration_sets() }
            }
            val active = async { remote.call(subject, "get_active_configuration_set") { configuration.activeSetId() } }
            ConfigurationSnapshot(sets.await().associate { it.id to it.configuration_data.toMap() }, active.await())
        }
    }
}

/**
 * A name-value list as strings, in its order ([NameValueMap]); values that are not strings are shown as CORBA prints
 * them. Names and short values are interned: every component and port repeats them (`dataport.data_type`,
 * `IDL:RTC/TimedLong:1.0`), and each read unmarshals new copies, which the tree kept for as long as it watched the
 * component. [valuesRepeat] says the whole list of values repeats too, as a port's does ([NameValueMap.of]).
 */
internal fun Array<NameValue>.toMap(valuesRepeat: Boolean = false): Map<String, String> {
    val names = ArrayList<String>(size)
    val values = ArrayList<String>(size)
    for (entry in this) {
        val value = (runCatching { entry.value.extract_string() }.getOrNull() ?: entry.value.toString()).shared()
        // A name given twice keeps its first place and its last value, as a map filled in the list's order does.
        when (val at = names.indexOf(entry.name)) {
            -1 -> {
                names += entry.name.intern()
                values += value
            }
            else -> values[at] = value
        }
    }
    return NameValueMap.of(names, values, valuesRepeat)
}

/**
 * This string, interned when it is short: names, types and descriptions that every component of a kind repeats, which
 * each read unmarshals anew. Longer ones are references and addresses, each its own.
 */
private fun String.shared(): String = if (length <= SHARED_LENGTH) intern() else this

/** The longest string [shared] interns. */
private const val SHARED_LENGTH = 64

private const val PARTICIPATING_BASE = 1000

private fun RTC.ExecutionKind.label(): String =
    listOf("PERIODIC", "EVENT_DRIVEN", "OTHER").getOrElse(value()) { "UNKNOWN" }
