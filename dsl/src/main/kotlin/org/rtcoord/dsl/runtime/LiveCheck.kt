package org.rtcoord.dsl.runtime

import kotlinx.coroutines.coroutineScope
import org.rtcoord.EventOptions
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.ManagerRef
import org.rtcoord.dsl.Target
import org.rtcoord.dsl.portRef
import java.nio.file.Paths

/** Something a script names that the live system lacks: [name] as the script writes it, and [reason]. */
public data class MissingName(val name: String, val reason: String)

/**
 * What a script names, checked against the live system without changing anything, as `rtcoord check`
 * does with a name server: every component it names (patterns excepted), port, manager, naming
 * context, configuration parameter its rules follow, and configuration set its modes' networks ask for.
 * Components a mode's network wants inactive may be absent.
 */
public class LiveCheck(private val tree: RtcTree) {
    /** What [coordination] names that the live system lacks, each once, in the order the script declares them. */
    public suspend fun missing(coordination: Coordination): List<MissingName> = coroutineScope {
        val plan = coordination.plan()
        val identities = Identities(tree, EventOptions(), this, {}, emptyMap())
        val engine = Engine(tree, identities, Paths.get(""), {})
        val missing = LinkedHashSet<MissingName>()
        suspend fun probe(name: String, read: suspend () -> Unit) {
            try {
                read()
            } catch (e: RtcException) {
                missing += MissingName(name, e.reason)
            } catch (e: IllegalArgumentException) {
                missing += MissingName(name, e.message ?: e.toString())
            }
        }
        suspend fun component(selector: String) = probe(selector) { identities.node(selector) }
        suspend fun port(path: String) = portRef(path).let { ref -> probe(path) { identities.node(ref.component.selector).port(ref.name) } }

        val patterns = plan.rules.map { it.pattern } + plan.machines.flatMap { it.eventPatterns }
        for (pattern in patterns) {
            when (val target = pattern.target) {
                is Target.Component -> if (!target.ref.isPattern) component(target.ref.selector)
                is Target.Port -> port(target.ref.toString())
                is Target.Manager -> probe(target.ref.selector) { engine.manager(ManagerRef(target.ref.selector)) }
                is Target.Context -> probe(target.ref.path) { tree.node(target.ref.path) }
            }
            val parameter = pattern.parameter ?: continue
            val owner = (pattern.target as? Target.Component)?.ref?.takeUnless { it.isPattern } ?: continue
            probe(parameter) {
                val sets = identities.node(owner.selector).configuration().sets
                require(sets.values.any { parameter in it }) {
                    "$owner has no parameter '$parameter' (parameters: ${sets.values.flatMap { it.keys }.distinct().sorted().joinToString().ifEmpty { "none" }})"
                }
            }
        }
        for (network in plan.machines.flatMap { machine -> (listOf(machine.root) + machine.modes).mapNotNull { it.network } }) {
            network.components.filterValues { it }.keys.forEach { component(it) }
            network.connections.filterValues { it }.keys.forEach { link -> port(link.from); port(link.to) }
            for ((component, set) in network.configurationSets) {
                probe(set) {
                    val sets = identities.node(component).configuration().sets
                    require(set in sets) { "$component has no configuration set '$set' (sets: ${sets.keys.sorted().joinToString()})" }
                }
            }
        }
        plan.supervisions.flatMap { it.children }.forEach { component(it.selector) }
        identities.close()
        missing.toList()
    }
}
