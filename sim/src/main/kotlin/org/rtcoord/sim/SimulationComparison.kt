package org.rtcoord.sim

import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.nameServerPath
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.SystemProfiles

/**
 * How a simulated system differs from the live one it was saved from, each difference one line: the components at their
 * naming paths, with their types, ports (kind, data type, interfaces), execution contexts (kind, rate, implementation)
 * and configuration sets (hidden ones too, every value, the active set); the connections with their properties; the
 * managers, what each hosts and can create.
 *
 * Both systems are read as `rtcoord profile save` reads one, so what the comparison sees is what a saved profile
 * carries; paths are compared below their name servers, and the object references a connection's ports publish, which
 * differ from one connection to the next, are not compared.
 */
public class SimulationComparison
private constructor(
    /** Every difference, one line each: what it concerns, then what the live system has and what the simulation has. */
    public val differences: List<String>,
    /** What was compared, for a report: `6 components, 4 connections, 3 managers`. */
    public val compared: String,
) {
    /** Whether the simulation matches the live system in everything compared. */
    public val matches: Boolean
        get() = differences.isEmpty()

    public companion object {
        /**
         * Compares the live system below [below] on [live]'s name servers with [simulation] below the same naming path
         * on its own naming service.
         */
        @JvmSynthetic
        public suspend fun of(live: RtcTree, below: RtcPath, simulation: SimulatedSystem): SimulationComparison =
            coroutineScope {
                val saved = async { SystemProfiles(live).save(below) }
                val simulated = async {
                    RtcTree(TreeConfig(nameServers = listOf(simulation.address))).use { tree ->
                        val path =
                            below.names.fold(nameServerPath(simulation.address)) { path, name -> path.child(name) }
                        SystemProfiles(tree).save(path)
                    }
                }
                between(saved.await(), simulated.await())
            }

        /** Compares [live], saved from the live system, with [simulated], saved from its simulation. */
        @JvmStatic
        public fun between(live: RtsProfile, simulated: RtsProfile): SimulationComparison {
            val differences = mutableListOf<String>()
            val liveComponents = live.components.associateBy { it.pathUri.belowNameServer() }
            val simulatedComponents = simulated.components.associateBy { it.pathUri.belowNameServer() }
            for (path in (liveComponents.keys + simulatedComponents.keys).sorted()) {
                val a = liveComponents[path]
                val b = simulatedComponents[path]
                when {
                    a == null -> differences += "$path: no component live, one simulated"
                    b == null -> differences += "$path: a component live, none simulated"
                    else -> differences += ComponentDifferences(path, a, b).all()
                }
            }
            val connections = ConnectionDifferences(live, simulated)
            differences += connections.differences()
            val managers = ManagerDifferences(live.ext.properties, simulated.ext.properties)
            differences += managers.differences()
            val compared =
                "${liveComponents.size} components, ${connections.count} connections, ${managers.count} managers"
            return SimulationComparison(differences, compared)
        }
    }
}

/** `host:port/ctx.host_cxt/laser0.rtc` as `/ctx.host_cxt/laser0.rtc`. */
internal fun String.belowNameServer(): String = "/" + trim('/').substringAfter('/', "")

/** A value of a difference's line: `none` for what is absent. */
internal fun String?.shown(): String = this ?: "none"
