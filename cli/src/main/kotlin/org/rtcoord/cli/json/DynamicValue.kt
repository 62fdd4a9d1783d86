package org.rtcoord.cli.json

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive

/**
 * A value whose shape is known only at run time (a decoded sample's members) as JSON: maps as objects, lists as arrays,
 * numbers and booleans as themselves, a number that is not finite and anything else as its text.
 */
internal fun dynamicJson(value: Any?): JsonElement =
    when (value) {
        null -> JsonNull
        is JsonElement -> value
        is String -> JsonPrimitive(value)
        is Boolean -> JsonPrimitive(value)
        is Double -> if (value.isFinite()) JsonPrimitive(value) else JsonPrimitive(value.toString())
        is Float -> if (value.isFinite()) JsonPrimitive(value) else JsonPrimitive(value.toString())
        is Number -> JsonPrimitive(value)
        is Map<*, *> -> JsonObject(value.entries.associate { (key, item) -> key.toString() to dynamicJson(item) })
        is Iterable<*> -> JsonArray(value.map(::dynamicJson))
        else -> JsonPrimitive(value.toString())
    }
