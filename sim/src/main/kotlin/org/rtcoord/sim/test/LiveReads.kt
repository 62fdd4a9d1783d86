package org.rtcoord.sim.test

import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle
import org.rtcoord.NotFoundException
import org.rtcoord.RtcTree
import org.rtcoord.dsl.Coordinator
import org.rtcoord.sim.SimulatedSystem

/**
 * The simulated [system] as it is now, asked through [tree]; the [coordinator]'s modes and [logged] lines as they are
 * now (a coordinator not made yet has no modes).
 */
internal class LiveReads(
    private val system: SimulatedSystem,
    private val tree: RtcTree,
    private val coordinator: Coordinator?,
    private val logged: List<String>,
) : SystemReads {
    override suspend fun state(component: String): LifeCycle? = bound(component)?.state()

    override suspend fun exists(component: String): Boolean = bound(component) != null

    /**
     * The component [name] as the tree finds it; null while the system has none, and while the tree does not find the
     * one it has: a manager makes a component before it binds its name, and until then no client sees it.
     */
    private suspend fun bound(name: String): ComponentNode? {
        if (system.components.none { it.instanceName == name }) return null
        return try {
            node(name)
        } catch (e: NotFoundException) {
            null
        }
    }

    override suspend fun names(): Set<String> = system.components.mapTo(HashSet()) { it.instanceName }

    override suspend fun snapshot(component: String): ComponentSnapshot = node(component).snapshot()

    override suspend fun node(component: String): ComponentNode = node(system, tree, component)

    override fun modeOf(machine: String): String? {
        val running =
            coordinator ?: throw IllegalArgumentException("no mode machine '$machine': the coordinator has not started")
        return running.machine(machine).mode.value
    }

    override val log: List<String>
        get() = logged.toList()

    companion object {
        /**
         * The component [name] of [system], found through [tree] where the system binds it; throws when the system has
         * none.
         */
        suspend fun node(system: SimulatedSystem, tree: RtcTree, name: String): ComponentNode {
            val simulated = system.component(name)
            return tree.component("/${system.address}/${(simulated.contexts + "$name.rtc").joinToString("/")}")
        }
    }
}
