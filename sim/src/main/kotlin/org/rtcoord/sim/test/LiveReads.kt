package org.rtcoord.sim.test

import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle
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
    override suspend fun state(component: String): LifeCycle? = if (exists(component)) node(component).state() else null

    override suspend fun exists(component: String): Boolean = system.components.any { it.instanceName == component }

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
