package org.rtcoord.dsl.internal

import java.util.concurrent.ConcurrentHashMap
import org.rtcoord.LifeCycle
import org.rtcoord.PortDisconnected
import org.rtcoord.RtcEvent
import org.rtcoord.dsl.ComponentRef
import org.rtcoord.dsl.EventPattern
import org.rtcoord.dsl.EventPatterns
import org.rtcoord.dsl.Link
import org.rtcoord.dsl.ModeMachine
import org.rtcoord.dsl.Network
import org.rtcoord.dsl.portRef

/**
 * What a mode machine watches of the networks its modes declare, and what breaks the one in force: a component it
 * requires active that enters ERROR, is lost, becomes unreachable or exits, or a connection it requires that is
 * removed.
 */
internal class NetworkWatch(machine: ModeMachine) {
    /** A watched pattern: of a [component] the networks require active, or of the out-port of a [link] they require. */
    private class Watched(val pattern: EventPattern<*>, val component: String?, val link: Link?) {
        val matcher = pattern.matcher()
    }

    private val watched: List<Watched> = run {
        val networks = (listOf(machine.root) + machine.modes).mapNotNull { it.network }
        val components = networks.flatMap { network -> network.components.filterValues { it }.keys }.distinct()
        val links = networks.flatMap { network -> network.connections.filterValues { it }.keys }.distinct()
        components.flatMap { name ->
            val ref = ComponentRef(name)
            listOf(
                    EventPatterns.state(ref, LifeCycle.ERROR),
                    EventPatterns.lost(ref),
                    EventPatterns.zombie(ref),
                    EventPatterns.finalized(ref),
                )
                .map { Watched(it, name, null) }
        } + links.map { link -> Watched(EventPatterns.disconnected(portRef(link.from)), null, link) }
    }

    /** The patterns to watch for as long as the machine runs. */
    val patterns: List<EventPattern<*>> = watched.map { it.pattern }

    /** The patterns subscribed so far. */
    private val subscribed = ConcurrentHashMap.newKeySet<EventPattern<*>>()

    /** The patterns not subscribed yet: what the networks name that did not exist when last tried. */
    fun unwatched(): List<EventPattern<*>> = patterns.filter { it !in subscribed }

    /** Notes that [patterns] are subscribed. */
    fun watching(patterns: List<EventPattern<*>>) {
        subscribed += patterns
    }

    /** Whether [patterns] are this watch's (not transitions'). */
    fun owns(patterns: List<EventPattern<*>>): Boolean = patterns.any { pattern ->
        watched.any { it.pattern === pattern }
    }

    /** Whether [event] is one of [patterns]'. */
    fun accepts(event: RtcEvent, patterns: List<EventPattern<*>>): Boolean = watched.any {
        it.pattern in patterns && it.matcher.match(event) != null
    }

    /**
     * What [event] (delivered for [patterns]) breaks of [network], established with [connectors] joining its links;
     * null when it breaks nothing the network requires.
     */
    fun breach(
        network: Network,
        connectors: Map<Link, List<String>>,
        event: RtcEvent,
        patterns: List<EventPattern<*>>,
    ): String? =
        watched
            .filter { it.pattern in patterns && it.matcher.match(event) != null }
            .firstNotNullOfOrNull { watch ->
                when {
                    watch.component != null ->
                        watch.pattern.description.takeIf { network.components[watch.component] == true }
                    watch.link != null &&
                        network.connections[watch.link] == true &&
                        (event as PortDisconnected).connector.id in connectors[watch.link].orEmpty() ->
                        "${watch.link} was disconnected"
                    else -> null
                }
            }
}
