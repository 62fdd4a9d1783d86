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

/**
 * What `cat` shows of a component: profile with its place in composites, execution contexts, ports
 * with their interfaces and connections and, when asked for, configuration. Read in one go, printed
 * afterwards.
 */
internal class ComponentReport private constructor(
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
                ) + listOfNotNull(snapshot.parent?.let { listOf("Parent", it) }) + listOf(listOf("Type", typeLabel)) +
                    listOfNotNull(fsm?.let { listOf("FSM state", it.text()) }),
                "  ",
            ),
        )
        if (long && snapshot.properties.isNotEmpty()) {
            add("  Properties")
            addAll(aligned(sorted(snapshot.properties), "    "))
        }
        add("  Execution contexts")
        val contextLines = aligned(
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
    fun toJson(): Map<String, Any?> = buildMap {
        put("path", path.toString())
        put("kind", "component")
        put("instanceName", snapshot.instanceName)
        put("typeName", snapshot.typeName)
        put("version", snapshot.version)
        put("vendor", snapshot.vendor)
        put("category", snapshot.category)
        put("description", snapshot.description)
        put("parent", snapshot.parent)
        put("type", typeLabel)
        put("state", snapshot.overallState.name)
        fsm?.let { put("fsm", fsm.toJson()) }
        put("properties", snapshot.properties.toSortedMap())
        put(
            "contexts",
            snapshot.contexts.map { context ->
                mapOf(
                    "handle" to context.handle,
                    "owned" to context.owned,
                    "kind" to context.kind,
                    "rate" to context.rate,
                    "running" to context.running,
                    "state" to context.state.name,
                    "participants" to context.participants,
                    "properties" to context.properties.toSortedMap(),
                )
            },
        )
        put("ports", ports.map { it.toJson() })
        configuration?.let { put("configuration", it.toJson(it.shownSets(showHidden = false))) }
    }

    /** The component's type as rtcat names it: monolithic or composite, and whether it is part of a composite. */
    private val typeLabel: String
        get() = (if (composition.isComposite) "Composite" else "Monolithic") + if (composition.isMember) " composite member" else ""

    companion object {
        /** Reads [component] now, with its FSM's state as [tree]'s model holds it; its configuration too when [withConfiguration]. */
        suspend fun read(tree: RtcTree, component: ComponentNode, withConfiguration: Boolean): ComponentReport = coroutineScope {
            val composition = async { component.composition() }
            component.refresh()
            val snapshot = component.snapshot()
            val configuration = if (withConfiguration) async { component.configuration() } else null
            val ports = snapshot.ports.map { port -> async { PortReport.read(component.port(port.name)) } }
            val fsm = tree.snapshot().component(component)?.fsm
            ComponentReport(component.path, snapshot, composition.await(), ports.awaitAll(), configuration?.await(), fsm)
        }
    }
}
