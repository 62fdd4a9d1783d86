package org.rtcoord.profile

import org.jspecify.annotations.Nullable

/**
 * The `rts_ext` part of an element (comment, visibility, location, free properties) and whatever else
 * the file had on it that the schema does not name, kept so a round trip loses nothing.
 */
public data class Extension(
    val comment: @Nullable String? = null,
    val visible: @Nullable Boolean? = null,
    val location: @Nullable Location? = null,
    /** `rtsExt:Properties` in file order. */
    val properties: Map<String, String> = emptyMap(),
    /** Attributes (XML) or scalar keys (YAML) the schema does not name, by the name written. */
    val unknownAttributes: Map<String, String> = emptyMap(),
    /** Elements (XML) or nested keys (YAML) the schema does not name, in file order. */
    val unknownElements: List<ForeignElement> = emptyList(),
)

/** Where RTSystemEditor draws an element. */
public data class Location(val x: Int, val y: Int, val width: Int, val height: Int, val direction: String = "RIGHT")

/** An element outside the schema, kept as read: its name as written, attributes, children and text. */
public data class ForeignElement(
    val name: String,
    val attributes: Map<String, String> = emptyMap(),
    val children: List<ForeignElement> = emptyList(),
    val text: String = "",
)
