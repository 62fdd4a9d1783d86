package org.rtcoord.cli

import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.Composition
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.FsmStatus
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.cli.json.ComponentReportJson
import org.rtcoord.cli.json.ContextJson
import org.rtcoord.cli.json.FsmJson

/**
 * What `cat` shows of a component: profile with its place in composites, execution contexts, ports with their
 * interfaces and connections and, when asked for, configuration. Read in one go, printed afterwards.
 */
internal class ComponentReport
private constructor(
    private val path: RtcPath,
    private val snapshot: ComponentSnapshot,
    private val composition: Composition,
    private val ports: List<PortReport>,
    private val configuration: ConfigurationSnapshot?,
    private val fsm: FsmStatus?,
) {
    /** The report as text; [long] adds properties, connector details and configuration sets. */
    fun lines(long: Boolean): List<String> = buildList {
        add("${path.name}  ${stateLabel(snapshot.overallState)}")
        addAll(
            aligned(
                listOf(
                    listOf("Instance name", snapshot.instanceName),
                    listOf("Type name", snapshot.typeName),
                    listOf("Version", snapshot.version),
                    listOf("Vendor", snapshot.vendor),
                    listOf("Category", snapshot.category),
                    listOf("Description", snapshot.description),
                ) +
                    listOfNotNull(snapshot.parent?.let { listOf("Parent", it) }) +
                    listOf(listOf("Type", typeLabel)) +
                    listOfNotNull(fsm?.let { listOf("FSM state", it.text()) }),
                "  ",
            )
        )
        if (long && snapshot.properties.isNotEmpty()) {
            add("  Properties")
            addAll(aligned(sorted(snapshot.properties), "    "))
        }
        add("  Execution contexts")
        val contextLines =
            aligned(
                snapshot.contexts.map { context ->
                    listOf(
                        context.handle.toString(),
                        context.kind,
                        "${context.rate} Hz",
                        if (context.running) "running" else "stopped",
                        stateLabel(context.state),
                        if (context.owned) "owned" else "participating",
                    )
                },
                "    ",
            )
        snapshot.contexts.zip(contextLines).forEach { (context, line) ->
            add(line)
            if (long) addAll(aligned(sorted(context.properties), "        "))
        }
        add("  Ports")
        ports.forEach { addAll(it.lines(long, "    ")) }
        configuration?.let { configuration ->
            add("  Configuration")
            addAll(configuration.lines(configuration.shownSets(showHidden = false), "    "))
        }
    }

    /** The report for `--json`. */
    fun toJson(): ComponentReportJson =
        ComponentReportJson(
            path.toString(),
            snapshot.instanceName,
            snapshot.typeName,
            snapshot.version,
            snapshot.vendor,
            snapshot.category,
            snapshot.description,
            snapshot.parent,
            typeLabel,
            snapshot.overallState.name,
            fsm?.let(FsmJson::of),
            snapshot.properties.toSortedMap(),
            snapshot.contexts.map { context ->
                ContextJson(
                    context.handle,
                    context.owned,
                    context.kind,
                    context.rate,
                    context.running,
                    context.state.name,
                    context.participants,
                    context.properties.toSortedMap(),
                )
            },
            ports.map { it.toJson() },
            configuration?.let { it.toJson(it.shownSets(showHidden = false)) },
        )

    /** The component's type as rtcat names it: monolithic or composite, and whether it is part of a composite. */
    private val typeLabel: String
        get() =
            (if (composition.isComposite) "Composite" else "Monolithic") +
                if (composition.isMember) " composite member" else ""

    companion object {
        /**
         * Reads [component] now, with its FSM's state as [tree]'s model holds it; its configuration too when
         * [withConfiguration].
         */
        suspend fun read(tree: RtcTree, component: ComponentNode, withConfiguration: Boolean): ComponentReport =
            coroutineScope {
                val composition = async { component.composition() }
                component.refresh()
                val snapshot = component.snapshot()
                val configuration = if (withConfiguration) async { component.configuration() } else null
                val ports = snapshot.ports.map { port -> async { PortReport.read(component.port(port.name)) } }
                val fsm = tree.snapshot().component(component)?.fsm
                ComponentReport(
                    component.path,
                    snapshot,
                    composition.await(),
                    ports.awaitAll(),
                    configuration?.await(),
                    fsm,
                )
            }
    }
}
