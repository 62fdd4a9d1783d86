package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Paths
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.KSerializer
import kotlinx.serialization.descriptors.PolymorphicKind
import kotlinx.serialization.descriptors.PrimitiveKind
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.descriptors.StructureKind
import kotlinx.serialization.descriptors.elementDescriptors
import kotlinx.serialization.json.JsonElement
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.cli.json.ComponentReportJson
import org.rtcoord.cli.json.ConfigurationJson
import org.rtcoord.cli.json.ConnectorJson
import org.rtcoord.cli.json.CreatedJson
import org.rtcoord.cli.json.DifferenceJson
import org.rtcoord.cli.json.EntryJson
import org.rtcoord.cli.json.EventJson
import org.rtcoord.cli.json.FoundJson
import org.rtcoord.cli.json.ManagerReportJson
import org.rtcoord.cli.json.ParameterJson
import org.rtcoord.cli.json.PlannedStepJson
import org.rtcoord.cli.json.PortJson
import org.rtcoord.cli.json.RestoreJson
import org.rtcoord.cli.json.SampleJson
import org.rtcoord.cli.json.Spread
import org.rtcoord.cli.json.StepOutcomeJson
import org.rtcoord.cli.serve.ComponentErrorJson
import org.rtcoord.cli.serve.CoordinatorJson
import org.rtcoord.cli.serve.LiveSnapshotJson
import org.rtcoord.cli.serve.NetworkJson
import org.rtcoord.cli.serve.RecordedUpdateJson
import org.rtcoord.cli.serve.TimelineEntryJson

/**
 * docs/json.md against the types that write the JSON: every type reachable from what rtcoord writes has a section, and
 * each section's table lists the type's fields, in the order they are written, with their JSON types (a sealed type's
 * variants in alphabetical order). A field added, renamed or retyped without the document fails here, with the table to
 * paste.
 */
@OptIn(ExperimentalSerializationApi::class)
class JsonFormatsDocTest {
    private val written: List<KSerializer<*>> =
        listOf(
            LiveSnapshotJson.serializer(),
            NetworkJson.serializer(),
            CoordinatorJson.serializer(),
            TimelineEntryJson.serializer(),
            ComponentReportJson.serializer(),
            ComponentErrorJson.serializer(),
            RecordedUpdateJson.serializer(),
            EventJson.serializer(),
            SampleJson.serializer(),
            EntryJson.serializer(),
            PortJson.serializer(),
            ManagerReportJson.serializer(),
            ConfigurationJson.serializer(),
            FoundJson.serializer(),
            ParameterJson.serializer(),
            CreatedJson.serializer(),
            ConnectorJson.serializer(),
            DifferenceJson.serializer(),
            PlannedStepJson.serializer(),
            StepOutcomeJson.serializer(),
            RestoreJson.serializer(),
        )

    @Test
    fun `docs json md lists every field of every type, in order, with its JSON type`() {
        val sections = documentedSections()
        val expected = LinkedHashMap<String, List<String>>()
        written.forEach { collect(it.descriptor, expected) }
        val wrong = expected.filter { (name, rows) -> sections[name] != rows }
        assertEquals(
            emptyMap<String, List<String>>(),
            wrong,
            "docs/json.md disagrees with the types; the tables they need:\n" +
                wrong.entries.joinToString("\n\n") { (name, rows) ->
                    "### $name\n\n| Field | Type | Meaning |\n|---|---|---|\n" + rows.joinToString("\n") { "$it |" }
                },
        )
        assertEquals(
            emptySet<String>(),
            sections.keys - expected.keys,
            "sections of docs/json.md that describe no type",
        )
    }

    /** Each `### Name` section's table rows as `| field | type`, the meaning left out. */
    private fun documentedSections(): Map<String, List<String>> {
        val root = Paths.get(System.getProperty("rtcoord.root", ".."))
        val lines = Files.readAllLines(root.resolve("docs/json.md"))
        val sections = LinkedHashMap<String, MutableList<String>>()
        var current: MutableList<String>? = null
        for (line in lines) {
            when {
                line.startsWith("### ") ->
                    current =
                        mutableListOf<String>().also {
                            sections[line.removePrefix("### ").trim().removeSurrounding("`")] = it
                        }
                line.startsWith("## ") -> current = null
                line.startsWith("| ") && current != null && !line.startsWith("| Field") -> {
                    val cells = line.split(" | ").map { it.trim().trim('|').trim() }
                    current += "| ${cells[0]} | ${cells[1]}"
                }
            }
        }
        return sections
    }

    /** [descriptor]'s rows, and those of every type it holds, by name. */
    private fun collect(descriptor: SerialDescriptor, into: MutableMap<String, List<String>>) {
        val type = descriptor
        when (type.kind) {
            StructureKind.LIST -> collect(type.getElementDescriptor(0), into)
            StructureKind.MAP -> collect(type.getElementDescriptor(1), into)
            PolymorphicKind.SEALED -> {
                if (isJsonElement(type) || nameOf(type) in into) return
                val variants = type.getElementDescriptor(1).elementDescriptors.toList()
                into[nameOf(type)] = variants.map { "| ${nameOf(it)} | variant" }.sorted()
                variants.forEach { collect(it, into) }
            }
            StructureKind.CLASS,
            StructureKind.OBJECT -> {
                if (nameOf(type) in into) return
                into[nameOf(type)] =
                    (0 until type.elementsCount).map { index ->
                        val element = type.getElementDescriptor(index)
                        val spread = type.getElementAnnotations(index).any { it is Spread }
                        if (spread) "| … | fields of ${nameOf(element)}"
                        else
                            "| `${type.getElementName(index)}` | ${label(element)}" +
                                (if (type.isElementOptional(index)) ", optional" else "")
                    }
                (0 until type.elementsCount).forEach { collect(type.getElementDescriptor(it), into) }
            }
            else -> Unit
        }
    }

    /** The JSON type a field holds, naming rtcoord's types by their section. */
    private fun label(descriptor: SerialDescriptor): String {
        val type = descriptor
        val base =
            when {
                isJsonElement(type) -> "any"
                type.kind == PrimitiveKind.STRING -> "string"
                type.kind == PrimitiveKind.BOOLEAN -> "boolean"
                type.kind is PrimitiveKind -> "number"
                type.kind == StructureKind.LIST -> "array of ${label(type.getElementDescriptor(0))}"
                type.kind == StructureKind.MAP -> "object of ${label(type.getElementDescriptor(1))}"
                else -> nameOf(type)
            }
        return if (descriptor.isNullable) "$base or null" else base
    }

    private fun isJsonElement(descriptor: SerialDescriptor) =
        descriptor.serialName.removeSuffix("?") == JsonElement.serializer().descriptor.serialName

    /** A type's section name: its class's simple name without `Json`. */
    private fun nameOf(descriptor: SerialDescriptor): String =
        descriptor.serialName.removeSuffix("?").substringAfterLast('.').removeSuffix("Json")
}
