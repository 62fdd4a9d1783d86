package org.rtcoord.dsl.internal

import org.rtcoord.LifeCycle
import org.rtcoord.dsl.ComponentRef
import org.rtcoord.dsl.Link
import org.rtcoord.dsl.Network
import org.rtcoord.dsl.Reaction
import org.rtcoord.dsl.portRef

/**
 * The live system as read for what a [Network] names: component states (null: absent), active sets (null: none active),
 * and for each link the ids of the connectors joining its ports (none: not connected, or a port is absent).
 */
internal class LiveNetwork(
    val states: Map<String, LifeCycle?>,
    val activeSets: Map<String, String?>,
    val links: Map<Link, List<String>>,
)

/** One change to the live system, named as the script names its objects (the failure reason starts with it). */
internal sealed class Step(val description: String) {
    abstract suspend fun apply(engine: Engine)

    class Deactivate(private val component: String) : Step("deactivate $component") {
        override suspend fun apply(engine: Engine) = ComponentRef(component).deactivate()
    }

    /** Removes the connectors read as joining the link: one another client removed since was not planned for. */
    class Disconnect(private val link: Link, private val connectors: List<String>) :
        Step("disconnect ${link.from} from ${link.to}") {
        override suspend fun apply(engine: Engine) {
            val from = portRef(link.from)
            engine.act(description, from.component, namesItself = true) { node ->
                connectors.forEach { node.port(from.name).disconnect(it) }
            }
        }
    }

    class ActivateSet(private val component: String, private val id: String) :
        Step("activate configuration set $id of $component") {
        override suspend fun apply(engine: Engine) = ComponentRef(component).activateConfigSet(id)
    }

    class Connect(private val link: Link, private val properties: Map<String, String>) :
        Step("connect ${link.from} to ${link.to}") {
        override suspend fun apply(engine: Engine) = Reaction(engine, null).connect(link.from, link.to, properties)
    }

    class Activate(private val component: String) : Step("activate $component") {
        override suspend fun apply(engine: Engine) = ComponentRef(component).activate()
    }

    override fun toString(): String = description
}

/**
 * The steps that bring [live] to [desired], in dependency order: stop the components that must stop (in reverse
 * declaration order), remove unwanted connections, switch configuration sets, make the missing connections, then start
 * the components that must run (in declaration order), so that nothing runs on a half-made network. Empty when [live]
 * already matches.
 */
internal fun plan(desired: Network, live: LiveNetwork): List<Step> {
    val stop =
        desired.components
            .filter { (component, active) -> !active && live.states[component] == LifeCycle.ACTIVE }
            .keys
            .reversed()
    val cut = desired.connections.filter { (link, present) -> !present && !live.links[link].isNullOrEmpty() }.keys
    val sets = desired.configurationSets.filter { (component, id) -> live.activeSets[component] != id }
    val join = desired.connections.filter { (link, present) -> present && live.links[link].isNullOrEmpty() }.keys
    val start =
        desired.components.filter { (component, active) -> active && live.states[component] != LifeCycle.ACTIVE }.keys
    return stop.map { Step.Deactivate(it) } +
        cut.map { Step.Disconnect(it, live.links.getValue(it)) } +
        sets.map { (component, id) -> Step.ActivateSet(component, id) } +
        join.map { Step.Connect(it, desired.properties[it].orEmpty()) } +
        start.map { Step.Activate(it) }
}
