package org.rtcoord.cli.json

import kotlinx.serialization.KSerializer
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonTransformingSerializer
import kotlinx.serialization.json.jsonObject

/**
 * Writes [T] as [generated] does, with the object of each [Spread] property written field by field in that property's
 * place. For writing only: the flat object does not say which field came from where.
 */
internal abstract class SpreadingSerializer<T : Any>(generated: KSerializer<T>) :
    JsonTransformingSerializer<T>(generated) {
    private val spread: Set<String> =
        (0 until generated.descriptor.elementsCount)
            .filter { index -> generated.descriptor.getElementAnnotations(index).any { it is Spread } }
            .mapTo(HashSet()) { generated.descriptor.getElementName(it) }

    override fun transformSerialize(element: JsonElement): JsonElement =
        JsonObject(
            buildMap {
                for ((name, value) in element.jsonObject) {
                    when {
                        name !in spread -> put(name, value)
                        value is JsonObject -> putAll(value)
                    }
                }
            }
        )
}
