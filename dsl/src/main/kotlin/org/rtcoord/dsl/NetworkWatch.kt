package org.rtcoord.dsl

import org.rtcoord.LifeCycle
import org.rtcoord.PortDisconnected
import org.rtcoord.RtcEvent

/**
 * What a mode machine watches of the networks its modes declare, and what breaks the one in force: a
 * component it requires active that enters ERROR, is lost, becomes unreachable or exits, or a connection
 * it requires that is removed.
 */
internal class NetworkWatch(engine: Engine, machine: ModeMachine) {
    /** A watched pattern: of a [component] the networks require active, or of the out-port of a [link] they require. */
    private class Watched(val pattern: EventPattern<*>, val component: String?, val link: Link?)

    private val watched: List<Watched> = run {
        val networks = (listOf(machine.root) + machine.modes).mapNotNull { it.network }
        val components = networks.flatMap { network -> network.components.filterValues { it }.keys }.distinct()
        val links = networks.flatMap { network -> network.connections.filterValues { it }.keys }.distinct()
        components.flatMap { name ->
            val ref = engine.componentRef(name)
            listOf(EventPatterns.state(ref, LifeCycle.ERROR), EventPatterns.lost(ref), EventPatterns.zombie(ref), EventPatterns.finalized(ref))
                .map { Watched(it, name, null) }
        } + links.map { link -> Watched(EventPatterns.disconnected(engine.portRef(link.from)), null, link) }
    }

    /** The patterns to watch for as long as the machine runs. */
    val patterns: List<EventPattern<*>> = watched.map { it.pattern }

    /** Whether [patterns] are this watch's (not transitions'). */
    fun owns(patterns: List<EventPattern<*>>): Boolean = patterns.any { pattern -> watched.any { it.pattern === pattern } }

    /**
     * What [event] (delivered for [patterns]) breaks of [network], established with [connectors] joining
     * its links; null when it breaks nothing the network requires.
     */
    fun breach(network: Network, connectors: Map<Link, List<String>>, event: RtcEvent, patterns: List<EventPattern<*>>): String? =
        watched.filter { it.pattern in patterns && it.pattern.accepts(event) }.firstNotNullOfOrNull { watch ->
            when {
                watch.component != null -> watch.pattern.description.takeIf { network.components[watch.component] == true }
                watch.link != null && network.connections[watch.link] == true && (event as PortDisconnected).connector.id in connectors[watch.link].orEmpty() ->
                    "${watch.link} was disconnected"
                else -> null
            }
        }
}
