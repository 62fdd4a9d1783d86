package org.rtcoord.sim.test

import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerDied
import org.rtcoord.NodeAppeared
import org.rtcoord.NodeVanished
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.SystemSnapshot

/**
 * The system and the coordinator as the events of a scenario told them, up to the last one applied: what an invariant
 * reads, so that it is checked against each event's outcome, not against a system that has moved on since. Components
 * by instance name (without `.rtc`). A component the events have not told of yet (the tree lists a naming context again
 * only every so often, so one just created may have no event yet) is read from [live], the system as it is now, until
 * they do. Changed by the scenario's one observer coroutine only.
 */
internal class SystemModel(private val live: SystemReads) : SystemReads {
    private val states = HashMap<String, MutableMap<Int, LifeCycle>>()
    private val nodes = HashMap<String, ComponentNode>()
    private val modes = HashMap<String, String?>()
    private val lines = ArrayList<String>()
    /** Components the events told are gone, until they tell of them again. */
    private val gone = HashSet<String>()

    /** Takes what the tree knew when the scenario's observation began. */
    fun start(snapshot: SystemSnapshot) {
        for (entry in snapshot.components) {
            val name = entry.node.name.removeSuffix(".rtc")
            nodes[name] = entry.node
            states[name] = entry.states.toMutableMap()
        }
    }

    fun apply(event: RtcEvent) {
        when (event) {
            is StateChanged -> state(event.source).put(event.handle, event.new)
            is NodeAppeared ->
                (event.child as? ComponentNode)?.let { node ->
                    val name = node.name.removeSuffix(".rtc")
                    nodes[name] = node
                    gone -= name
                    val known = event.snapshot?.contexts?.associate { it.handle to it.state }.orEmpty()
                    states.getOrPut(name) { HashMap() }.putAll(known)
                }
            is NodeVanished -> gone(event.child.name)
            is ComponentFinalized -> gone(event.source.name)
            is ManagerDied -> event.components.forEach { gone(it.name) }
            else -> Unit
        }
    }

    fun mode(machine: String, mode: String?) {
        modes[machine] = mode
    }

    fun log(line: String) {
        lines += line
    }

    private fun state(node: ComponentNode): MutableMap<Int, LifeCycle> {
        val name = node.name.removeSuffix(".rtc")
        nodes[name] = node
        gone -= name
        return states.getOrPut(name) { HashMap() }
    }

    private fun gone(path: String) {
        val name = path.removeSuffix(".rtc")
        nodes.remove(name)
        states.remove(name)
        gone += name
    }

    override suspend fun state(component: String): LifeCycle? {
        val known = states[component] ?: return if (component in gone) null else live.state(component)
        return known[0] ?: known.entries.minByOrNull { it.key }?.value ?: LifeCycle.UNKNOWN
    }

    override suspend fun exists(component: String): Boolean =
        component in nodes || (component !in gone && live.exists(component))

    override suspend fun names(): Set<String> = nodes.keys + (live.names() - gone)

    override suspend fun snapshot(component: String): ComponentSnapshot {
        val node = node(component)
        return node.snapshots.value ?: node.snapshot()
    }

    override suspend fun node(component: String): ComponentNode = nodes[component] ?: live.node(component)

    override fun modeOf(machine: String): String? {
        require(machine in modes) {
            "no mode machine '$machine' (machines: ${modes.keys.joinToString().ifEmpty { "none" }})"
        }
        return modes[machine]
    }

    override val log: List<String>
        get() = lines.toList()
}
