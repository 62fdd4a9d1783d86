package org.rtcoord.profile.internal

import org.rtcoord.profile.ComponentGroup
import org.rtcoord.profile.Condition
import org.rtcoord.profile.ConfigurationSet
import org.rtcoord.profile.ExecutionContext
import org.rtcoord.profile.OrderedTarget
import org.rtcoord.profile.Ordering
import org.rtcoord.profile.OrderingKind
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfilePort
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent

/** An [RtsProfile] from its root element, whichever format held it: RTSProfile's schema, once. */
internal object ProfileDecoder {
    fun decode(root: ProfileTree): RtsProfile =
        with(root) {
            RtsProfile(
                id = requiredText("id"),
                version = text("version") ?: "0.2",
                abstract = text("abstract").orEmpty(),
                creationDate = date("creationDate"),
                updateDate = date("updateDate"),
                components = list("components").map(::component),
                // RTSystemEditor writes groupID, the schema groupId.
                groups =
                    list("groups").map {
                        it.run {
                            ComponentGroup(
                                text("groupID") ?: requiredText("groupId"),
                                list("members").map(::targetComponent),
                                ext(),
                            )
                        }
                    },
                dataPortConnectors =
                    list("dataPortConnectors").map { connector(it, "sourceDataPort", "targetDataPort") },
                servicePortConnectors =
                    list("servicePortConnectors").map { connector(it, "sourceServicePort", "targetServicePort") },
                orderings =
                    OrderingKind.entries
                        .mapNotNull { kind -> child(kind.yamlKey)?.let { kind to ordering(it) } }
                        .toMap(),
                ext = ext(),
            )
        }

    private fun component(tree: ProfileTree) =
        with(tree) {
            ProfileComponent(
                id = requiredText("id"),
                pathUri = text("pathUri").orEmpty(),
                instanceName = requiredText("instanceName"),
                activeConfigurationSet = text("activeConfigurationSet").orEmpty(),
                compositeType = text("compositeType") ?: "None",
                isRequired = boolean("isRequired") ?: false,
                dataPorts = list("dataPorts").map { it.run { ProfilePort(requiredText("name"), ext()) } },
                servicePorts = list("servicePorts").map { it.run { ProfilePort(requiredText("name"), ext()) } },
                configurationSets =
                    list("configurationSets").map { set ->
                        set.run {
                            val data =
                                list("configurationData").associate {
                                    it.run { (requiredText("name") to text("data").orEmpty()).also { ext() } }
                                }
                            ConfigurationSet(requiredText("id"), data, ext())
                        }
                    },
                executionContexts =
                    list("executionContexts").map {
                        it.run {
                            ExecutionContext(
                                requiredText("id"),
                                text("kind") ?: "PERIODIC",
                                double("rate"),
                                list("participants").map(::participant),
                                ext(),
                            )
                        }
                    },
                participants = list("participants").map(::participant),
                ext = ext(),
            )
        }

    /** A participant wraps one target: `<rts:Participants><rts:Participant .../>`, `- participant: {...}`. */
    private fun participant(tree: ProfileTree): TargetComponent =
        targetComponent(tree.required("participant")).also { tree.ext() }

    private fun targetComponent(tree: ProfileTree) =
        with(tree) {
            TargetComponent(
                requiredText("componentId"),
                requiredText("instanceName"),
                text("portName"),
                text("id"),
                ext(),
            )
        }

    private fun connector(tree: ProfileTree, sourceKey: String, targetKey: String) =
        with(tree) {
            PortConnector(
                connectorId = text("connectorId").orEmpty(),
                name = text("name").orEmpty(),
                source = targetComponent(required(sourceKey)),
                target = targetComponent(required(targetKey)),
                dataType = text("dataType"),
                interfaceType = text("interfaceType"),
                dataflowType = text("dataflowType"),
                subscriptionType = text("subscriptionType"),
                pushInterval = double("pushInterval"),
                transMethod = text("transMethod"),
                ext = ext(),
            )
        }

    private fun ordering(tree: ProfileTree) = Ordering(tree.list("targets").map(::target), tree.ext())

    private fun target(tree: ProfileTree) =
        with(tree) {
            val sequence = int("sequence") ?: 0
            val component = targetComponent(required("targetComponent"))
            // The XML form holds the condition in the target itself, the YAML form under `condition`.
            val holder = child("condition") ?: this
            val wait = holder.child("waitTime")
            val preceding = holder.child("preceding")
            val condition =
                when {
                    wait != null -> Condition.WaitTime(wait.int("waitTime") ?: 0).also { wait.ext() }
                    preceding != null ->
                        preceding.run {
                            Condition.Preceding(
                                    list("precedingComponents").map(::targetComponent),
                                    int("timeout") ?: 0,
                                    text("sendingTiming") ?: "ASYNC",
                                )
                                .also { ext() }
                        }
                    else -> Condition.None
                }
            if (holder !== this) holder.ext()
            OrderedTarget(sequence, component, condition, ext())
        }
}
