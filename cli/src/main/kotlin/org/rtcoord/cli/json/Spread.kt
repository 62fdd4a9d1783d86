package org.rtcoord.cli.json

import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.SerialInfo

/**
 * Marks a property whose object is written field by field in its place, so the JSON stays one flat object (an event's
 * own fields beside its time and path). The class's serializer must be a [SpreadingSerializer]; the API document lists
 * the spread fields where the property stands.
 */
@OptIn(ExperimentalSerializationApi::class)
@SerialInfo
@Target(AnnotationTarget.PROPERTY)
internal annotation class Spread
