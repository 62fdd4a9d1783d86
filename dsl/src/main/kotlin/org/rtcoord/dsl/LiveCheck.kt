package org.rtcoord.dsl

import java.nio.file.Files
import java.nio.file.Path
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.toList
import org.rtcoord.EventOptions
import org.rtcoord.ManagerNode
import org.rtcoord.NodeFilters
import org.rtcoord.NodeKind
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.dsl.internal.Engine
import org.rtcoord.dsl.internal.Findings
import org.rtcoord.dsl.internal.Identities
import org.rtcoord.dsl.internal.plan
import org.rtcoord.dsl.script.CompiledCoordinator
import org.rtcoord.dsl.script.NameKind
import org.rtcoord.dsl.script.WrittenName
import org.rtcoord.dsl.script.WrittenNames

/**
 * What a script names, checked against the live system without changing anything, as `rtcoord check` does with a name
 * server: every target of its rules, data rules, mode transitions and supervisors (ports included), the components,
 * connections and configuration sets its modes' networks ask for, the parameters its rules follow, and every name its
 * text passes to `component`, `port`, `manager`, `context`, `connect`, `profile` and their kin anywhere, handlers
 * included (see [ScriptCheck]). Components a mode's network wants inactive may be absent.
 */
public class LiveCheck(private val tree: RtcTree) {
    /** Checks [coordination], evaluated from [script], whose text says where each name is written. */
    public suspend fun check(coordination: Coordination, script: Path): ScriptCheck = coroutineScope {
        val text =
            if (CompiledCoordinator.isCompiled(script)) CompiledCoordinator.source(script) else Files.readString(script)
        val written = WrittenNames.read(text)
        val identities = Identities(tree, EventOptions(), this, {}, emptyMap())
        val probe = Probe(tree, identities, Engine(tree, identities, coordination.directory, {}))
        try {
            probe.plan(coordination.plan())
            written.forEach { probe.written(it, coordination.directory) }
        } finally {
            identities.close()
        }
        Findings(script, text, written).of(probe.missing.values)
    }

    /**
     * A name the live system lacks, [reason] why; [rule] when it is a parameter or configuration set that what names it
     * lacks: a rule or mode that starts but can never fire or be reached.
     */
    internal class Miss(val name: String, val reason: String, val rule: Boolean, val at: WrittenName? = null)

    /** Looks names up, recording what is missing; each name once. */
    private class Probe(private val tree: RtcTree, private val identities: Identities, private val engine: Engine) {
        val missing = LinkedHashMap<String, Miss>()

        private suspend fun probe(
            name: String,
            rule: Boolean = false,
            at: WrittenName? = null,
            read: suspend () -> Unit,
        ) {
            val key = at?.position?.let { "$it $name" } ?: name
            if (key in missing) return
            try {
                read()
            } catch (e: RtcException) {
                missing[key] = Miss(name, e.reason, rule, at)
            } catch (e: IllegalArgumentException) {
                missing[key] = Miss(name, e.message ?: e.toString(), rule, at)
            }
        }

        private suspend fun component(selector: String, at: WrittenName? = null) {
            if (!ComponentRef(selector).isPattern) probe(selector, at = at) { identities.node(selector) }
        }

        /**
         * A port (a rule on a port that is not there stops the coordinator's start: it is missing, not a rule that
         * cannot fire).
         */
        private suspend fun port(path: String, at: WrittenName? = null) =
            probe(path, at = at) {
                val ref = portRef(path)
                identities.node(ref.component.selector).port(ref.name)
            }

        suspend fun plan(plan: Plan) {
            val patterns = plan.rules.map { it.pattern } + plan.machines.flatMap { it.eventPatterns }
            for (pattern in patterns) {
                when (val target = pattern.target) {
                    is Target.Component -> component(target.ref.selector)
                    is Target.Port -> port(target.ref.toString())
                    is Target.Manager -> probe(target.ref.selector) { engine.manager(ManagerRef(target.ref.selector)) }
                    is Target.Context -> probe(target.ref.path) { tree.node(target.ref.path) }
                    // Nothing to find: records come to the tree's log inputs from whoever sends them.
                    Target.Logs -> Unit
                }
                val parameter = pattern.parameter ?: continue
                val owner = (pattern.target as? Target.Component)?.ref?.takeUnless { it.isPattern } ?: continue
                if (owner.selector in missing) continue
                probe(parameter, rule = true) {
                    val sets = identities.node(owner.selector).configuration().sets
                    require(sets.values.any { parameter in it }) {
                        "$owner has no parameter '$parameter' (parameters: ${sets.values.flatMap { it.keys }.distinct().sorted().joinToString().ifEmpty { "none" }})"
                    }
                }
            }
            plan.dataRules.forEach { port(it.port.toString()) }
            for (network in
                plan.machines.flatMap { machine -> (listOf(machine.root) + machine.modes).mapNotNull { it.network } }) {
                network.components.filterValues { it }.keys.forEach { component(it) }
                network.connections
                    .filterValues { it }
                    .keys
                    .forEach { link ->
                        port(link.from)
                        port(link.to)
                    }
                for ((component, set) in network.configurationSets) {
                    if (component in missing) continue
                    probe(set, rule = true) {
                        val sets = identities.node(component).configuration().sets
                        require(set in sets) {
                            "$component has no configuration set '$set' (sets: ${sets.keys.sorted().joinToString()})"
                        }
                    }
                }
            }
            plan.supervisions.flatMap { it.children }.forEach { component(it.selector) }
        }

        /** Looks up what [use] names, if the text says it. */
        suspend fun written(use: WrittenName, directory: Path) {
            val name = use.name ?: return
            when (use.kind) {
                NameKind.COMPONENT -> component(name, use)
                NameKind.PORT -> port(name, use)
                NameKind.MANAGER -> probe(name, at = use) { engine.manager(ManagerRef(name)) }
                NameKind.CONTEXT -> probe(name, at = use) { tree.node(name) }
                NameKind.PROFILE ->
                    probe(name, at = use) {
                        try {
                            directory.profile(name)
                        } catch (e: RtcException) {
                            throw e
                        } catch (e: Exception) {
                            throw IllegalArgumentException("cannot read ${directory.resolve(name)}: ${e.message ?: e}")
                        }
                    }
                NameKind.CREATED_TYPE ->
                    probe(name, at = use) {
                        val (types, modules) = creatable()
                        require(name in types || name in modules) {
                            "no manager can create or load '$name' (factories: ${types.sorted().joinToString().ifEmpty { "none" }}; " +
                                "loadable modules: ${modules.sorted().joinToString().ifEmpty { "none" }})"
                        }
                    }
                NameKind.CREATED_NAME -> Unit
            }
        }

        private var creatable: Pair<Set<String>, Set<String>>? = null

        /**
         * The types the managers on the name servers have factories for, and the modules they could load (by file name
         * without its extension, as OpenRTM-aist loads a type's module): what a `create` may ask for, whichever manager
         * it goes to.
         */
        private suspend fun creatable(): Pair<Set<String>, Set<String>> =
            creatable
                ?: run {
                    val managers =
                        tree
                            .find(predicate = NodeFilters.kind(NodeKind.MANAGER))
                            .toList()
                            .filterIsInstance<ManagerNode>()
                    val types =
                        managers
                            .flatMap { manager ->
                                manager.factories().mapNotNull { it["implementation_id"] ?: it["type_name"] }
                            }
                            .toSet()
                    val modules =
                        managers
                            .flatMap { manager ->
                                manager
                                    .loadableModules()
                                    .mapNotNull { it["module_file_name"] ?: it["module_file_path"] }
                                    .map { it.substringAfterLast('/').substringBefore('.') }
                            }
                            .toSet()
                    (types to modules).also { creatable = it }
                }
    }
}
