package org.rtcoord.dsl

import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.ContextRateChanged
import org.rtcoord.EventOptions
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerComponentChanged
import org.rtcoord.Node
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import org.rtcoord.Subscription

/**
 * One kind of event of one target (a component entering ERROR, a port losing a connection): what rules
 * and mode transitions are triggered by. [description] is how scripts, logs and `check` name it.
 * Most patterns watch for events of their [type]; one that also reads other events ([watched] wider
 * than [type]) turns those into its [type] with [translate], or drops them.
 */
internal class EventPattern<E : RtcEvent>(
    val description: String,
    val target: Target,
    val type: Class<E>,
    val watched: Class<out RtcEvent> = type,
    private val translate: (RtcEvent) -> E? = { event -> if (type.isInstance(event)) type.cast(event) else null },
    private val prepare: suspend (Node) -> Unit = {},
    val matches: (E) -> Boolean,
) {
    /** A rule running [handler] on these events when every guard holds. */
    fun rule(guards: List<Guard>, handler: suspend Reaction.(E) -> Unit): Rule<E> = Rule(this, guards, handler)

    /** [event] as one of these, or null when it is not one. */
    fun match(event: RtcEvent): E? = translate(event)?.takeIf(matches)

    /** Whether [event] is one of these. */
    fun accepts(event: RtcEvent): Boolean = match(event) != null

    /**
     * Hands every event this pattern reads from [node] to [deliver], once [others] watching with it (the
     * same [watched] type) read what they follow of [node].
     */
    suspend fun watch(tree: RtcTree, node: Node, options: EventOptions, others: List<EventPattern<*>> = emptyList(), deliver: suspend (RtcEvent) -> Unit): Subscription {
        (listOf(this) + others).distinct().forEach { it.prepare(node) }
        return tree.on(node, watched, options) { deliver(it) }
    }
}

/** The event kinds of each target, shared by rules and transitions so that both name and match them alike. */
internal object EventPatterns {
    fun state(target: ComponentRef, state: LifeCycle) =
        EventPattern("$target enters $state", Target.Component(target), StateChanged::class.java) { it.new == state }

    fun stateChanged(target: ComponentRef) = EventPattern("$target changes state", Target.Component(target), StateChanged::class.java) { true }

    /** Changes of the effective value of [name]: in the active set, or by a switch to a set that holds another value. */
    fun configParam(target: ComponentRef, name: String): EventPattern<ParameterChanged> {
        val value = EffectiveValue(name)
        return EventPattern(
            "$target parameter $name changes", Target.Component(target), ParameterChanged::class.java,
            watched = RtcEvent::class.java, translate = value::changeOf, prepare = value::prepare,
        ) { true }
    }

    fun configSetActivated(target: ComponentRef): EventPattern<ConfigurationSetActivated> {
        val active = ActiveSetSwitch()
        return EventPattern(
            "$target activates a configuration set", Target.Component(target), ConfigurationSetActivated::class.java,
            watched = ConfigurationSetActivated::class.java, translate = active::switchOf, prepare = active::prepare,
        ) { true }
    }

    fun rateChanged(target: ComponentRef) = EventPattern("$target rate changes", Target.Component(target), ContextRateChanged::class.java) { true }

    fun connected(target: ComponentRef) = EventPattern("$target connects", Target.Component(target), PortConnected::class.java) { true }

    fun disconnected(target: ComponentRef) = EventPattern("$target disconnects", Target.Component(target), PortDisconnected::class.java) { true }

    fun lost(target: ComponentRef) = EventPattern("$target is lost", Target.Component(target), HeartbeatLost::class.java) { true }

    fun zombie(target: ComponentRef) = EventPattern("$target becomes a zombie", Target.Component(target), BecameZombie::class.java) { true }

    fun recovered(target: ComponentRef) = EventPattern("$target recovers", Target.Component(target), Recovered::class.java) { true }

    fun finalized(target: ComponentRef) = EventPattern("$target exits", Target.Component(target), ComponentFinalized::class.java) { true }

    fun connected(target: PortRef) = EventPattern("$target connects", Target.Port(target), PortConnected::class.java) { it.port == target.name }

    fun disconnected(target: PortRef) = EventPattern("$target disconnects", Target.Port(target), PortDisconnected::class.java) { it.port == target.name }

    fun created(target: ManagerRef) =
        EventPattern("$target creates a component", Target.Manager(target), ManagerComponentChanged::class.java) { it.created }

    fun deleted(target: ManagerRef) =
        EventPattern("$target deletes a component", Target.Manager(target), ManagerComponentChanged::class.java) { !it.created }

    fun appeared(target: ContextRef) =
        EventPattern("$target gains a binding", Target.Context(target), NodeAppeared::class.java) { it.source.path.toString() == RtcPath.parse(target.path).toString() }

    fun vanished(target: ContextRef) =
        EventPattern("$target loses a binding", Target.Context(target), NodeVanished::class.java) { it.source.path.toString() == RtcPath.parse(target.path).toString() }
}
