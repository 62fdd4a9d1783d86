package org.rtcoord.cli.serve

import org.rtcoord.ComponentNode
import org.rtcoord.DirectoryNode
import org.rtcoord.ManagerNode
import org.rtcoord.Node
import org.rtcoord.PortKind
import org.rtcoord.SystemSnapshot
import org.rtcoord.ZombieNode
import org.rtcoord.cli.ComponentNetwork
import org.rtcoord.cli.json.FsmJson

/**
 * The system below [top] as the page draws it, from what the tree holds: naming contexts and name servers as boxes
 * around what they bind, components with their states, data and service connections (from [ComponentNetwork]), managers
 * with the components they host, zombies, and directories that could not be listed. Each component carries its ports
 * (in, out, service) and each connection names the ports it joins, as RTSystemEditor draws them. Every id is a whole
 * path. States are [model]'s, the tree's events up to its sequence.
 */
internal class NetworkView(private val top: Node, private val model: SystemSnapshot) {
    /** Components below [top] the tree has not read yet: the view leaves them out until they are. */
    fun unread(): List<ComponentNode> =
        walk(top).filterIsInstance<ComponentNode>().filter { it.snapshots.value == null }

    /** The view as the page reads it. */
    suspend fun toJson(): NetworkJson {
        val network = ComponentNetwork(top)
        val graph = network.graph()
        val nodes = walk(top)
        val managers = nodes.filterIsInstance<ManagerNode>()
        val directories = nodes.filterIsInstance<DirectoryNode>().filter { it !is ManagerNode }
        val components =
            network.components.map { component ->
                val snapshot = component.snapshots.value!!
                val entry = model.component(component)
                NetworkComponentJson(
                    id = component.path.toString(),
                    name = snapshot.instanceName,
                    type = snapshot.typeName,
                    parent = component.path.parent?.toString(),
                    // As the tree's events tell it: a read may run ahead of them (a deactivation held).
                    state = (entry?.overallState ?: org.rtcoord.LifeCycle.UNKNOWN).name,
                    hostedBy = managers.firstOrNull { manager -> hosts(manager, component) }?.path?.toString(),
                    fsm = entry?.fsm?.let(FsmJson::of),
                    ports =
                        snapshot.ports.map { port ->
                            NetworkPortJson(
                                name = port.name,
                                kind = side(port.kind),
                                dataType = port.dataType,
                                interfaces =
                                    port.interfaces.map {
                                        "${it.polarity.name.lowercase()} ${it.instanceName}: ${it.typeName}"
                                    },
                            )
                        },
                )
            }
        val known = components.map { it.id }.toSet()
        val vertices = graph.vertices.associate { vertex -> vertex.id to wholePath(vertex.id) }
        return NetworkJson(
            top = top.path.toString(),
            sequence = model.sequence,
            contexts =
                directories.map { directory ->
                    NamingContextJson(
                        id = directory.path.toString(),
                        name = if (directory.path.names.isEmpty()) directory.path.toString() else directory.name,
                        parent =
                            directory.path.parent
                                ?.takeIf { parent -> directories.any { it.path == parent } }
                                ?.toString(),
                        reachable = directory.listed.value != null,
                    )
                },
            components = components,
            external =
                graph.vertices.filter { it.state == null }.map { ExternalJson(vertices.getValue(it.id), it.label) },
            managers =
                managers.map { manager ->
                    ManagerBoxJson(
                        id = manager.path.toString(),
                        name = manager.name,
                        // A slave is drawn in the naming context of its master.
                        parent =
                            generateSequence(manager.path.parent) { it.parent }
                                .firstOrNull { above -> directories.any { it.path == above } }
                                ?.toString(),
                        // What it hosts: its components, and the slaves a master lists.
                        hosts =
                            components.filter { it.hostedBy == manager.path.toString() }.map { it.id } +
                                managers.filter { it.path.parent == manager.path }.map { it.path.toString() },
                    )
                },
            zombies =
                nodes.filterIsInstance<ZombieNode>().map { zombie ->
                    ZombieJson(zombie.path.toString(), zombie.name, zombie.path.parent?.toString(), zombie.cause.reason)
                },
            connections =
                graph.edges
                    .map { edge ->
                        ConnectionLineJson(
                            source = vertices.getValue(edge.from),
                            target = vertices.getValue(edge.to),
                            sourcePort = edge.tail,
                            targetPort = edge.head,
                            label = edge.label,
                            kind = if (edge.directed) "data" else "service",
                        )
                    }
                    .filter { it.source in known || it.target in known },
        )
    }

    /** Where the page draws a port of [kind]: in-ports on the left, out-ports on the right, the rest below. */
    private fun side(kind: PortKind): String =
        when (kind) {
            PortKind.DATA_IN -> "in"
            PortKind.DATA_OUT -> "out"
            PortKind.SERVICE,
            PortKind.OTHER -> "service"
        }

    /** A vertex id of [ComponentNetwork]: a path below [top], or already whole. */
    private fun wholePath(id: String): String =
        if (id.startsWith("/")) id else "${top.path.toString().trimEnd('/')}/$id"

    private fun hosts(manager: ManagerNode, component: ComponentNode): Boolean =
        manager.listed.value.orEmpty().any { it is ComponentNode && it.isSameComponent(component) }

    /** [node] and everything the tree has listed below it. */
    private fun walk(node: Node): List<Node> =
        listOf(node) +
            when (node) {
                is DirectoryNode -> node.listed.value.orEmpty().flatMap(::walk)
                else -> emptyList()
            }
}
