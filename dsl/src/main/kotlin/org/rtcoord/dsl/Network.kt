@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl

import kotlin.time.Duration
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.RtsProfile

/** A data connection from out-port [from] to in-port [to], each `component:port` (plain names get `.rtc`). */
public class Link(public val from: String, public val to: String) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("from" to from, "to" to to)

    override fun toString(): String = "$from -> $to"
}

/**
 * The network a mode declares (see [NetworkBuilder]), or that of the active modes merged, inner modes overriding outer
 * ones. It names only what it constrains: components, connections and configuration sets it does not mention are left
 * as they are.
 *
 * @property components whether each component must be ACTIVE (true) or must not be (false).
 * @property connections whether each connection must exist (true) or must not (false).
 * @property configurationSets the configuration set each component must have active.
 * @property stepDeadline how long each step of bringing the system here may take; null: the default.
 */
public class Network
internal constructor(
    public val components: Map<String, Boolean>,
    public val connections: Map<Link, Boolean>,
    public val configurationSets: Map<String, String>,
    public val stepDeadline: Duration?,
    internal val properties: Map<Link, Map<String, String>>,
) {
    /** One line per kind of constraint, as `check` lists them. */
    public val description: List<String>
        get() =
            listOfNotNull(
                components.filterValues { it }.keys.takeIf { it.isNotEmpty() }?.let { "active ${it.joinToString()}" },
                components
                    .filterValues { !it }
                    .keys
                    .takeIf { it.isNotEmpty() }
                    ?.let { "inactive ${it.joinToString()}" },
                connections
                    .filterValues { it }
                    .keys
                    .takeIf { it.isNotEmpty() }
                    ?.let { "connected ${it.joinToString()}" },
                connections
                    .filterValues { !it }
                    .keys
                    .takeIf { it.isNotEmpty() }
                    ?.let { "not connected ${it.joinToString()}" },
                configurationSets
                    .takeIf { it.isNotEmpty() }
                    ?.let { sets -> "configuration sets ${sets.entries.joinToString { "${it.key}=${it.value}" }}" },
                stepDeadline?.let { "each step within $it" },
            )

    /** This network with [inner]'s constraints taking precedence where both say something. */
    internal fun overriddenBy(inner: Network): Network =
        Network(
            components + inner.components,
            connections + inner.connections,
            configurationSets + inner.configurationSets,
            inner.stepDeadline ?: stepDeadline,
            properties + inner.properties,
        )
}

/**
 * Declares the network a mode needs: `network { active("laser0.rtc"); connected("laser0.rtc:laser",
 * "laser_localise0.rtc:laser"); configSet("laser_localise0.rtc", "default") }`, or takes it from an RTSProfile:
 * `network { profile("nav.xml") }`. Components are named as in `component(...)` (a name or a full path, not a pattern);
 * ports as `component:port`.
 */
@RtcDsl
public class NetworkBuilder internal constructor(private val readProfile: (String) -> RtsProfile) {
    private val components = linkedMapOf<String, Boolean>()
    private val connections = linkedMapOf<Link, Boolean>()
    private val configurationSets = linkedMapOf<String, String>()
    private val properties = linkedMapOf<Link, Map<String, String>>()
    internal val problems = mutableListOf<String>()

    /** How long each step (activate, connect, ...) may take before the mode's network counts as failed. */
    public var stepDeadline: Duration? = null

    /** These components must be ACTIVE. */
    public fun active(vararg components: String) {
        components.forEach { require(component(it), true) }
    }

    /** These components must not be ACTIVE (INACTIVE, left in ERROR for whoever recovers them, or absent). */
    public fun inactive(vararg components: String) {
        components.forEach { require(component(it), false) }
    }

    /** Out-port [from] must be connected to in-port [to]; a new connection gets connector [properties]. */
    public fun connected(from: String, to: String, properties: Map<String, String> = emptyMap()) {
        val link = Link(port(from), port(to))
        require(link, true)
        if (properties.isNotEmpty()) this.properties[link] = properties
    }

    /** No connection may join port [from] and port [to] (met too when either does not exist). */
    public fun disconnected(from: String, to: String) {
        require(Link(port(from), port(to)), false)
    }

    /** [component] must have configuration set [id] active. */
    public fun configSet(component: String, id: String) {
        val name = component(component)
        configurationSets[name]
            ?.takeIf { it != id }
            ?.let { problems += "$name is given two configuration sets ($it, $id)" }
        configurationSets[name] = id
    }

    /**
     * Everything the RTSProfile [file] (XML or YAML, relative to the script's directory) says of the network: its
     * required components active (with [active] false their states are left alone), its connections made with the
     * profile's connector properties, and each component's active configuration set. Components are named by the
     * profile's paths (`pathUri`). Optional components (`isRequired` false) and their connections are left alone, as a
     * restore leaves them. Configuration values are not written, only sets switched: `restoreProfile(file)` in an entry
     * action writes them. The file is read when the script is evaluated; one that cannot be read is a problem of the
     * machine.
     */
    public fun profile(file: String, active: Boolean = true) {
        val profile =
            try {
                readProfile(file)
            } catch (e: ProfileFormatException) {
                problems += "profile ${e.message}"
                return
            }
        val required = profile.components.filter { it.isRequired }
        val paths = required.associate { it.instanceName to "/" + it.pathUri.removePrefix("/") }
        if (active) required.forEach { active(paths.getValue(it.instanceName)) }
        for (connector in profile.dataPortConnectors + profile.servicePortConnectors) {
            val from = profile.component(connector.source)?.let { paths[it.instanceName] } ?: continue
            val to = profile.component(connector.target)?.let { paths[it.instanceName] } ?: continue
            val fromPort = connector.source.shortPortName ?: continue
            val toPort = connector.target.shortPortName ?: continue
            connected("$from:$fromPort", "$to:$toPort", connector.connectionProperties())
        }
        required
            .filter { it.activeConfigurationSet.isNotEmpty() }
            .forEach { configSet(paths.getValue(it.instanceName), it.activeConfigurationSet) }
    }

    internal fun build(): Network =
        Network(components.toMap(), connections.toMap(), configurationSets.toMap(), stepDeadline, properties.toMap())

    private fun require(component: String, active: Boolean) {
        if (components[component] == !active) problems += "$component is declared both active and inactive"
        components[component] = active
    }

    private fun require(link: Link, present: Boolean) {
        if (connections[link] == !present) problems += "$link is declared both connected and not connected"
        connections[link] = present
    }

    private fun component(selector: String): String {
        if (selector.any { it == '*' || it == '?' })
            problems += "'$selector' is a pattern; a network names single components"
        return normalized(selector)
    }

    private fun port(path: String): String {
        val split = path.lastIndexOf(':')
        if (split <= 0 || split == path.length - 1 || '/' in path.substring(split)) {
            problems += "not a port: '$path' (write component:port)"
            return path
        }
        return "${component(path.substring(0, split))}:${path.substring(split + 1)}"
    }

    private companion object {
        /**
         * A plain name gets `.rtc`, as `component(...)` finds it, so that `laser0` and `laser0.rtc` are one component.
         */
        fun normalized(selector: String): String =
            if (selector.startsWith("/") || selector.startsWith("corbaloc:") || '.' in selector) selector
            else "$selector.rtc"
    }
}
