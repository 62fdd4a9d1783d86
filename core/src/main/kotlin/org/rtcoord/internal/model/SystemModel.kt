package org.rtcoord.internal.model

import org.rtcoord.BecameZombie
import org.rtcoord.ComponentEntryImpl
import org.rtcoord.ComponentFinalized
import org.rtcoord.DirectoryNode
import org.rtcoord.FsmStateChanged
import org.rtcoord.FsmStatusImpl
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerDied
import org.rtcoord.ManagerReturned
import org.rtcoord.NameServerEntryImpl
import org.rtcoord.NameServerLost
import org.rtcoord.NameServerNode
import org.rtcoord.NameServerReturned
import org.rtcoord.ObserverFlavour
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.StateChanged
import org.rtcoord.SystemSnapshot
import org.rtcoord.SystemSnapshotImpl
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.componentsListed
import org.rtcoord.internal.unknownFsmStatus

/**
 * The tree's one truth about the live system: what its events have told, numbered. Every event the tree publishes
 * passes through [publish], which gives it the next sequence number, applies it to the model and hands it to its sinks
 * in one step; [snapshot] reads the model in a step of the same lock. So a snapshot at N holds exactly the events up to
 * N, and a sink registered before it gets every later one.
 *
 * The model keeps what no node keeps: the states as the events told them (a watched component's read may run ahead of
 * its events while a deactivation is held), name servers that do not answer and managers found dead. Structure (which
 * nodes exist) stays with the nodes' listings, walked here without a call ([componentsListed]). A component nobody
 * watches has no events: its states are its latest read, taken here and nowhere else, so that no view chooses between
 * the model and a read (see the owners' table in docs/architecture.md).
 */
internal class SystemModel(private val nameServers: () -> List<NameServerNode>) {
    private class Outage(val since: Long, val cause: RtcException)

    private var sequence = 0L
    /** Each watched component's states by context handle, as its events last told them. */
    private val states = HashMap<ComponentObject, Map<Int, LifeCycle>>()
    private val dead = HashSet<ComponentObject>()
    private val methods = HashMap<ComponentObject, WatchMethod>()
    /** Each watched FSM component's state as its last [FsmStateChanged] told it. */
    private val fsmStates = HashMap<ComponentObject, String>()
    private val outages = HashMap<RtcPath, Outage>()
    private val managerOutages = LinkedHashMap<RtcPath, ManagerDied>()

    /**
     * Numbers [events], applies them and hands each to [deliver], in order; [deliver] must not wait. For a watched
     * [component], [published] are its states by handle as its events tell them after [events].
     */
    fun publish(
        events: List<RtcEvent>,
        component: ComponentObject? = null,
        published: Map<Int, LifeCycle>? = null,
        deliver: (RtcEvent) -> Unit,
    ) {
        synchronized(this) {
            if (component != null && published != null) states[component] = published
            for (event in events) {
                event.sequence = ++sequence
                apply(event)
                deliver(event)
            }
        }
    }

    /** Nobody watches [component] any more: its states are read from its snapshots again. */
    fun unwatched(component: ComponentObject) {
        synchronized(this) {
            states.remove(component)
            methods.remove(component)
            fsmStates.remove(component)
        }
    }

    /** Whether [component] is watched, by push or by polling, and answers: its monitor would notice it stop. */
    fun answers(component: ComponentObject): Boolean =
        synchronized(this) {
            methods[component].let { it is WatchMethod.Pushed || it is WatchMethod.Polled } && component !in dead
        }

    /** When [server] was lost and why; null while it answers. */
    fun outageOf(server: NameServerNode): Pair<Long, RtcException>? =
        synchronized(this) { outages[server.path]?.let { it.since to it.cause } }

    /** The model now: every component the listings found, at its canonical path, with its states as told. */
    fun snapshot(root: DirectoryNode): SystemSnapshot =
        synchronized(this) {
            val components =
                componentsListed(listOf(root)).map { node ->
                    val component = node.component
                    val told =
                        states[component]
                            ?: node.snapshots.value?.contexts?.associate { it.handle to it.state }.orEmpty()
                    val method = methods[component]
                    val fsm =
                        fsmStates[component]?.let { FsmStatusImpl(it, null) }
                            ?: unknownFsmStatus(method).takeIf { node.snapshots.value?.offersFsmService == true }
                    ComponentEntryImpl(node, told, alive = component !in dead, watchMethod = method, fsm = fsm)
                }
            val servers =
                nameServers().map { server ->
                    outages[server.path].let { NameServerEntryImpl(server, it?.since, it?.cause) }
                }
            SystemSnapshotImpl(sequence, components, servers, managerOutages.values.toList())
        }

    private fun apply(event: RtcEvent) {
        when (event) {
            is StateChanged ->
                states[event.source.component]?.let {
                    states[event.source.component] = it + (event.handle to event.new)
                }
            is BecameZombie -> dead += event.source.component
            is ComponentFinalized -> dead += event.source.component
            is Recovered -> dead -= event.source.component
            is WatchMethodChanged -> {
                methods[event.source.component] = event.new
                // Only an FSM4RTC observer hears the machine: watched otherwise, its state is no longer known.
                if ((event.new as? WatchMethod.Pushed)?.flavour != ObserverFlavour.OMG)
                    fsmStates.remove(event.source.component)
            }
            is FsmStateChanged -> fsmStates[event.source.component] = event.new
            is ManagerDied -> managerOutages[event.source.path] = event
            is ManagerReturned -> managerOutages.remove(event.source.path)
            is NameServerLost -> outages[event.source.path] = Outage(event.noticedAt, event.cause)
            is NameServerReturned -> outages.remove(event.source.path)
            else -> Unit
        }
    }
}
