package org.rtcoord.profile.internal

import org.rtcoord.profile.Extension
import org.rtcoord.profile.ForeignElement
import org.rtcoord.profile.Location
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.RtsProfile
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
        val document =
            try {
                val settings = LoadSettings.builder().setLabel(source).setMaxAliasesForCollections(10).build()
                Composer(settings, ParserImpl(settings, StreamReader(settings, text))).singleNode.orElse(null)
            } catch (e: MarkedYamlEngineException) {
                throw ProfileFormatException(
                    source,
                    e.problemMark.map { it.line + 1 }.orElse(0),
                    "not valid YAML: ${e.problem}",
                )
            } catch (e: YamlEngineException) {
                throw ProfileFormatException(source, 0, "not valid YAML: ${e.message}")
            } ?: throw ProfileFormatException(source, 0, "empty")
        return ProfileDecoder.decode(Tree(mapping(document, "the document")).required("rtsProfile"))
    }

    private fun mapping(node: Node, what: String): MappingNode =
        node as? MappingNode ?: fail("$what is not a mapping", node)

    private fun fail(reason: String, node: Node?): Nothing =
        throw ProfileFormatException(source, node?.startMark?.map { it.line + 1 }?.orElse(0) ?: 0, reason)

    /** One mapping: keys are its keys; the tool data are `rtsExt::` keys. */
    private inner class Tree(private val mapping: MappingNode) : ProfileTree {
        private val entries = mapping.value.associate { (it.keyNode as? ScalarNode)?.value.orEmpty() to it.valueNode }
        private val taken = mutableSetOf<String>()

        override fun text(key: String): String? = node(key)?.let { scalar(key, it) }

        override fun child(key: String): ProfileTree? = node(key)?.let { Tree(mapping(it, "'$key'")) }

        override fun list(key: String): List<ProfileTree> =
            when (val node = node(key)) {
                null -> emptyList()
                is SequenceNode -> node.value.map { Tree(mapping(it, "an item of '$key'")) }
                is ScalarNode ->
                    if (node.value.isEmpty() || node.value == "null") emptyList() else fail("$key is not a list", node)
                else -> fail("$key is not a list", node)
            }

        /** As rtsprofile writes it (year, month, ... keys) or as text. */
        override fun date(key: String): String =
            when (val node = node(key)) {
                null -> ""
                is MappingNode ->
                    Tree(node).run {
                        fun part(name: String) = int(name) ?: 0
                        "%04d-%02d-%02dT%02d:%02d:%02d"
                            .format(
                                part("year"),
                                part("month"),
                                part("day"),
                                part("hour"),
                                part("minute"),
                                part("second"),
                            )
                    }
                else -> scalar(key, node)
            }

        override fun missing(key: String): Nothing = fail("no '$key' here", mapping)

        override fun missingChild(key: String): Nothing = missing(key)

        override fun invalid(key: String, value: String, wanted: String): Nothing =
            fail("$key '$value' is not $wanted", entries[key])

        override fun ext(): Extension {
            val comment = text("${EXT}comment")
            val visible = boolean("${EXT}visible")
            val location =
                child("${EXT}location")?.run {
                    Location(
                        int("x") ?: 0,
                        int("y") ?: 0,
                        int("width") ?: 0,
                        int("height") ?: 0,
                        text("direction") ?: "RIGHT",
                    )
                }
            val properties =
                list("${EXT}properties").associate { it.run { requiredText("name") to text("value").orEmpty() } }
            val rest = entries.filterKeys { it !in taken }
            val attributes = rest.filterValues { it is ScalarNode }.mapValues { (it.value as ScalarNode).value }
            val elements = rest.filterValues { it !is ScalarNode }.flatMap { (key, value) -> foreign(key, value) }
            return Extension(comment, visible, location, properties, attributes, elements)
        }

        private fun node(key: String): Node? = entries[key]?.also { taken += key }

        private fun scalar(key: String, node: Node): String =
            (node as? ScalarNode)?.value ?: fail("$key is not a single value", node)
    }

    /** A nested value the schema does not name: a mapping becomes one element, a list one element per item. */
    private fun foreign(key: String, node: Node): List<ForeignElement> =
        when (node) {
            is ScalarNode -> listOf(ForeignElement(key, text = node.value))
            is SequenceNode -> node.value.flatMap { foreign(key, it) }
            is MappingNode -> {
                val pairs = node.value.map { (it.keyNode as? ScalarNode)?.value.orEmpty() to it.valueNode }
                listOf(
                    ForeignElement(
                        key,
                        pairs.filter { it.second is ScalarNode }.associate { (k, v) -> k to (v as ScalarNode).value },
                        pairs.filter { it.second !is ScalarNode }.flatMap { (k, v) -> foreign(k, v) },
                    )
                )
            }
            else -> emptyList()
        }

    private companion object {
        const val EXT = "rtsExt::"
    }
}
