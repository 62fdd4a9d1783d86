package org.rtcoord.profile.internal

import java.time.LocalDateTime
import java.time.format.DateTimeFormatter
import java.time.temporal.ChronoUnit
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.PortInterface
import org.rtcoord.PortKind
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.internal.componentsFound
import org.rtcoord.profile.ConfigurationSet
import org.rtcoord.profile.ExecutionContext
import org.rtcoord.profile.Extension
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfilePort
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent

/** Saves the running system as a profile, as rtcryo does. */
internal class SystemCapture(private val tree: RtcTree) {
    suspend fun capture(below: RtcPath, onlyConnected: Boolean, systemId: String, abstract: String): RtsProfile {
        tree.refresh(below)
        // Naming-context paths only, as rtcryo: a component below its manager is the same component.
        val nodes = componentsFound(listOf(tree.node(below))) { it.path.names.none { name -> name.endsWith(".mgr") } }
        val snapshots = nodes.associateWith { it.snapshot() }
        val chosen =
            if (onlyConnected)
                nodes.filter { node -> snapshots.getValue(node).ports.any { it.connectors.isNotEmpty() } }
            else nodes
        val components = chosen.map { component(it, snapshots.getValue(it)) }
        val byInstance = components.associateBy { it.instanceName }
        val data = mutableListOf<PortConnector>()
        val service = mutableListOf<PortConnector>()
        val seen = mutableSetOf<String>()
        for (node in chosen) {
            val snapshot = snapshots.getValue(node)
            for (port in snapshot.ports.filter { it.connectors.isNotEmpty() }) {
                // A data connection is recorded from its out-port, a service one from the first port that shows it.
                if (port.kind == PortKind.DATA_IN) continue
                for (connection in node.port(port.name).connections()) {
                    if (!seen.add(connection.id)) continue
                    val others = connection.ports.filter { it.fullName != port.fullName }
                    val peer = others.firstOrNull() ?: continue
                    val peerInstance = peer.fullName.substringBefore('.')
                    val peerComponent = byInstance[peerInstance] ?: continue
                    val source = end(byInstance.getValue(snapshot.instanceName), port.fullName)
                    val target = end(peerComponent, peer.fullName)
                    val properties = withoutReferences(connection.properties)
                    if (port.kind == PortKind.DATA_OUT) {
                        data +=
                            PortConnector(
                                connection.id,
                                connection.name,
                                source,
                                target,
                                dataType = properties["dataport.data_type"] ?: port.dataType,
                                interfaceType = properties["dataport.interface_type"] ?: "corba_cdr",
                                dataflowType = properties["dataport.dataflow_type"] ?: "push",
                                subscriptionType = properties["dataport.subscription_type"],
                                ext = Extension(properties = properties),
                            )
                    } else {
                        service +=
                            PortConnector(
                                connection.id,
                                connection.name,
                                source,
                                target,
                                ext = Extension(properties = properties),
                            )
                    }
                }
            }
        }
        val now = LocalDateTime.now().truncatedTo(ChronoUnit.SECONDS).format(DateTimeFormatter.ISO_LOCAL_DATE_TIME)
        return RtsProfile(
            systemId,
            abstract = abstract,
            creationDate = now,
            updateDate = now,
            components = components,
            dataPortConnectors = data,
            servicePortConnectors = service,
            ext = Extension(properties = ManagerCapture(tree).properties(below, byInstance.keys)),
        )
    }

    private suspend fun component(node: ComponentNode, s: ComponentSnapshot): ProfileComponent {
        val configuration = node.configuration()
        return ProfileComponent(
            id = componentId(s),
            pathUri = node.path.toString().removePrefix("/"),
            instanceName = s.instanceName,
            activeConfigurationSet = configuration.activeSet.orEmpty(),
            isRequired = true,
            // A port's kind and data type, as RTSystemEditor records them: what a simulator builds the port from.
            dataPorts =
                s.ports
                    .filter { it.kind == PortKind.DATA_IN || it.kind == PortKind.DATA_OUT }
                    .map { port ->
                        val kind = if (port.kind == PortKind.DATA_IN) "DataInPort" else "DataOutPort"
                        ProfilePort(
                            port.name,
                            Extension(
                                properties =
                                    listOfNotNull(
                                            "port.port_type" to kind,
                                            port.dataType?.let { "dataport.data_type" to it },
                                        )
                                        .toMap()
                            ),
                        )
                    },
            servicePorts =
                s.ports
                    .filter { it.kind == PortKind.SERVICE }
                    .map { port ->
                        ProfilePort(
                            port.name,
                            Extension(
                                properties =
                                    mapOf("port.port_type" to "CorbaPort") + interfaceProperties(port.interfaces)
                            ),
                        )
                    },
            // Hidden sets too, as rtcryo saves them: `__constraints__` tells a simulator what the parameters accept.
            configurationSets = configuration.sets.toSortedMap().map { (id, values) -> ConfigurationSet(id, values) },
            executionContexts =
                s.contexts
                    .filter { it.owned }
                    .map { context ->
                        val type = context.properties["type"]?.let { mapOf(CONTEXT_TYPE to it) }.orEmpty()
                        ExecutionContext(
                            context.handle.toString(),
                            context.kind.uppercase(),
                            context.rate,
                            ext = Extension(properties = type),
                        )
                    },
            ext = Extension(properties = mapOf(COMPONENT_PATH_ID to node.path.toString().removePrefix("/"))),
        )
    }

    private fun end(component: ProfileComponent, fullName: String) =
        TargetComponent(
            component.id,
            component.instanceName,
            fullName,
            ext = Extension(properties = mapOf(COMPONENT_PATH_ID to component.pathUri)),
        )

    internal companion object {
        /** The property of a saved execution context naming its implementation, as its profile's `type` does. */
        const val CONTEXT_TYPE = "type"

        /**
         * The prefix of a service port's property for one of its interfaces: `rtcoord.interface.provided.<instance>` =
         * its type.
         */
        const val INTERFACE = "rtcoord.interface"

        fun componentId(s: ComponentSnapshot) = "RTC:${s.vendor}:${s.category}:${s.typeName}:${s.version}"

        /**
         * A service port's interfaces in their order, as the schema has no place for them:
         * `rtcoord.interface.<polarity>.<instance>` = type.
         */
        fun interfaceProperties(interfaces: List<PortInterface>): Map<String, String> = interfaces.associate {
            "$INTERFACE.${it.polarity.name.lowercase()}.${it.instanceName}" to it.typeName
        }

        /** Sets such as `__constraints__` describe parameters; they are not configuration to restore. */
        fun isHidden(set: String) = set.startsWith("__") && set.endsWith("__")
    }
}
