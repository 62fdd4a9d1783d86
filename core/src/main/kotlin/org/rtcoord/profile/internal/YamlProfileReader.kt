package org.rtcoord.profile.internal

import org.rtcoord.profile.ComponentGroup
import org.rtcoord.profile.Condition
import org.rtcoord.profile.ConfigurationSet
import org.rtcoord.profile.ExecutionContext
import org.rtcoord.profile.Extension
import org.rtcoord.profile.ForeignElement
import org.rtcoord.profile.Location
import org.rtcoord.profile.OrderedTarget
import org.rtcoord.profile.Ordering
import org.rtcoord.profile.OrderingKind
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.ProfilePort
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.TargetComponent
import org.snakeyaml.engine.v2.api.LoadSettings
import org.snakeyaml.engine.v2.composer.Composer
import org.snakeyaml.engine.v2.exceptions.MarkedYamlEngineException
import org.snakeyaml.engine.v2.exceptions.YamlEngineException
import org.snakeyaml.engine.v2.nodes.MappingNode
import org.snakeyaml.engine.v2.nodes.Node
import org.snakeyaml.engine.v2.nodes.ScalarNode
import org.snakeyaml.engine.v2.nodes.SequenceNode
import org.snakeyaml.engine.v2.parser.ParserImpl
import org.snakeyaml.engine.v2.scanner.StreamReader

/** Reads the YAML form, as rtsprofile writes it (`rtsProfile:` at the top); [source] names the file in errors. */
internal class YamlProfileReader(private val source: String) {
    fun read(text: String): RtsProfile {
        val document = try {
            val settings = LoadSettings.builder().setLabel(source).setMaxAliasesForCollections(10).build()
            Composer(settings, ParserImpl(settings, StreamReader(settings, text))).singleNode.orElse(null)
        } catch (e: MarkedYamlEngineException) {
            throw ProfileFormatException(source, e.problemMark.map { it.line + 1 }.orElse(0), "not valid YAML: ${e.problem}")
        } catch (e: YamlEngineException) {
            throw ProfileFormatException(source, 0, "not valid YAML: ${e.message}")
        } ?: throw ProfileFormatException(source, 0, "empty")
        val top = Fields(map(document, "the document"))
        val root = Fields(map(top.required("rtsProfile"), "rtsProfile"))
        return with(root) {
            RtsProfile(
                id = text("id") ?: fail("rtsProfile has no id"),
                version = text("version") ?: "0.2",
                abstract = text("abstract").orEmpty(),
                creationDate = date("creationDate"),
                updateDate = date("updateDate"),
                components = list("components").map { component(Fields(map(it, "a component"))) },
                groups = list("groups").map { g -> Fields(map(g, "a group")).run { ComponentGroup(requiredText("groupId"), list("members").map { targetComponent(it) }, ext()) } },
                dataPortConnectors = list("dataPortConnectors").map { connector(Fields(map(it, "a connector")), "sourceDataPort", "targetDataPort") },
                servicePortConnectors = list("servicePortConnectors").map { connector(Fields(map(it, "a connector")), "sourceServicePort", "targetServicePort") },
                orderings = OrderingKind.entries.mapNotNull { kind -> node(kind.yamlKey)?.let { kind to ordering(it) } }.toMap(),
                ext = ext(),
            ).also { top.ext() }
        }
    }

    private fun component(f: Fields) = with(f) {
        ProfileComponent(
            id = requiredText("id"),
            pathUri = text("pathUri").orEmpty(),
            instanceName = requiredText("instanceName"),
            activeConfigurationSet = text("activeConfigurationSet").orEmpty(),
            compositeType = text("compositeType") ?: "None",
            isRequired = boolean("isRequired") ?: false,
            dataPorts = list("dataPorts").map { p -> Fields(map(p, "a port")).run { ProfilePort(requiredText("name"), ext()) } },
            servicePorts = list("servicePorts").map { p -> Fields(map(p, "a port")).run { ProfilePort(requiredText("name"), ext()) } },
            configurationSets = list("configurationSets").map { s ->
                Fields(map(s, "a configuration set")).run {
                    val data = list("configurationData").associate { d -> Fields(map(d, "configuration data")).run { requiredText("name") to text("data").orEmpty() } }
                    ConfigurationSet(requiredText("id"), data, ext())
                }
            },
            executionContexts = list("executionContexts").map { e ->
                Fields(map(e, "an execution context")).run {
                    ExecutionContext(requiredText("id"), text("kind") ?: "PERIODIC", double("rate"), list("participants").map { participant(it) }, ext())
                }
            },
            participants = list("participants").map { participant(it) },
            ext = ext(),
        )
    }

    /** `- participant: {componentId: ..., instanceName: ...}`. */
    private fun participant(node: Node) = Fields(map(node, "a participant")).run { targetComponent(required("participant")).also { ext() } }

    private fun targetComponent(node: Node) = Fields(map(node, "a target")).run {
        TargetComponent(requiredText("componentId"), requiredText("instanceName"), text("portName"), text("id"), ext())
    }

    private fun connector(f: Fields, sourceKey: String, targetKey: String) = with(f) {
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

    private fun ordering(node: Node) = Fields(map(node, "an ordering")).run { Ordering(list("targets").map { target(Fields(map(it, "a target"))) }, ext()) }

    private fun target(f: Fields) = with(f) {
        val sequence = int("sequence") ?: 0
        val component = targetComponent(required("targetComponent"))
        val condition = node("condition")?.let { c ->
            Fields(map(c, "a condition")).run {
                val wait = node("waitTime")
                val preceding = node("preceding")
                when {
                    wait != null -> Condition.WaitTime(Fields(map(wait, "waitTime")).int("waitTime") ?: 0)
                    preceding != null -> Fields(map(preceding, "preceding")).run {
                        Condition.Preceding(list("precedingComponents").map { targetComponent(it) }, int("timeout") ?: 0, text("sendingTiming") ?: "ASYNC")
                    }
                    else -> Condition.None
                }
            }
        } ?: Condition.None
        OrderedTarget(sequence, component, condition, ext())
    }

    private fun map(node: Node, what: String): MappingNode = node as? MappingNode ?: fail("$what is not a mapping", node)

    private fun fail(reason: String, node: Node? = null): Nothing =
        throw ProfileFormatException(source, node?.startMark?.map { it.line + 1 }?.orElse(0) ?: 0, reason)

    /** The keys of one mapping, each taken at most once, so that [ext] can keep what nothing took. */
    private inner class Fields(private val mapping: MappingNode) {
        private val entries = mapping.value.associate { (it.keyNode as? ScalarNode)?.value.orEmpty() to it.valueNode }
        private val taken = mutableSetOf<String>()

        fun node(key: String): Node? = entries[key]?.also { taken += key }

        fun required(key: String): Node = node(key) ?: fail("no '$key' here", mapping)

        fun text(key: String): String? = node(key)?.let { scalar(key, it) }

        fun requiredText(key: String): String = scalar(key, required(key))

        fun int(key: String): Int? = text(key)?.let { it.trim().toIntOrNull() ?: fail("$key '$it' is not an integer", entries[key]) }

        fun double(key: String): Double? = text(key)?.let { it.trim().toDoubleOrNull() ?: fail("$key '$it' is not a number", entries[key]) }

        fun boolean(key: String): Boolean? = text(key)?.let {
            when (it.trim().lowercase()) {
                "true" -> true
                "false" -> false
                else -> fail("$key '$it' is not true or false", entries[key])
            }
        }

        fun list(key: String): List<Node> = when (val node = node(key)) {
            null -> emptyList()
            is SequenceNode -> node.value
            is ScalarNode -> if (node.value.isEmpty() || node.value == "null") emptyList() else fail("$key is not a list", node)
            else -> fail("$key is not a list", node)
        }

        /** A date as rtsprofile writes it (year, month, ... keys) or as text. */
        fun date(key: String): String = when (val node = node(key)) {
            null -> ""
            is MappingNode -> Fields(node).run {
                fun part(name: String) = int(name) ?: 0
                "%04d-%02d-%02dT%02d:%02d:%02d".format(part("year"), part("month"), part("day"), part("hour"), part("minute"), part("second"))
            }
            else -> scalar(key, node)
        }

        /** The `rtsExt::` keys and everything not taken; call it last. */
        fun ext(): Extension {
            val comment = text("${EXT}comment")
            val visible = boolean("${EXT}visible")
            val location = node("${EXT}location")?.let { Fields(map(it, "a location")).run { Location(int("x") ?: 0, int("y") ?: 0, int("width") ?: 0, int("height") ?: 0, text("direction") ?: "RIGHT") } }
            val properties = list("${EXT}properties").associate { p -> Fields(map(p, "a property")).run { requiredText("name") to text("value").orEmpty() } }
            val rest = entries.filterKeys { it !in taken }
            val attributes = rest.filterValues { it is ScalarNode }.mapValues { (it.value as ScalarNode).value }
            val elements = rest.filterValues { it !is ScalarNode }.flatMap { (key, value) -> foreign(key, value) }
            return Extension(comment, visible, location, properties, attributes, elements)
        }

        private fun scalar(key: String, node: Node): String = (node as? ScalarNode)?.value ?: fail("$key is not a single value", node)
    }

    /** A nested value the schema does not name: a mapping becomes one element, a list one element per item. */
    private fun foreign(key: String, node: Node): List<ForeignElement> = when (node) {
        is ScalarNode -> listOf(ForeignElement(key, text = node.value))
        is SequenceNode -> node.value.flatMap { foreign(key, it) }
        is MappingNode -> {
            val pairs = node.value.map { (it.keyNode as? ScalarNode)?.value.orEmpty() to it.valueNode }
            listOf(
                ForeignElement(
                    key,
                    pairs.filter { it.second is ScalarNode }.associate { (k, v) -> k to (v as ScalarNode).value },
                    pairs.filter { it.second !is ScalarNode }.flatMap { (k, v) -> foreign(k, v) },
                ),
            )
        }
        else -> emptyList()
    }

    private companion object {
        const val EXT = "rtsExt::"
    }
}
