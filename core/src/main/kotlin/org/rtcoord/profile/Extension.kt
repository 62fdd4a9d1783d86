package org.rtcoord.profile

import org.jspecify.annotations.Nullable
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/**
 * The `rts_ext` part of an element (comment, visibility, location, free properties) and whatever else the file had on
 * it that the schema does not name, kept so a round trip loses nothing.
 */
public class Extension
@JvmOverloads
constructor(
    public val comment: @Nullable String? = null,
    public val visible: @Nullable Boolean? = null,
    public val location: @Nullable Location? = null,
    /** `rtsExt:Properties` in file order. */
    public val properties: Map<String, String> = emptyMap(),
    /** Attributes (XML) or scalar keys (YAML) the schema does not name, by the name written. */
    public val unknownAttributes: Map<String, String> = emptyMap(),
    /** Elements (XML) or nested keys (YAML) the schema does not name, in file order. */
    public val unknownElements: List<ForeignElement> = emptyList(),
) : ValueObject() {
    /** This extension with another [visible] flag, or none. */
    public fun withVisible(visible: @Nullable Boolean?): Extension = copy(visible = visible)

    /** This extension with [properties] instead of its own. */
    public fun withProperties(properties: Map<String, String>): Extension = copy(properties = properties)

    /** This extension without what the schema does not name: no unknown attributes or elements. */
    public fun withoutUnknown(): Extension = copy(unknownAttributes = emptyMap(), unknownElements = emptyList())

    private fun copy(
        visible: Boolean? = this.visible,
        properties: Map<String, String> = this.properties,
        unknownAttributes: Map<String, String> = this.unknownAttributes,
        unknownElements: List<ForeignElement> = this.unknownElements,
    ) = Extension(comment, visible, location, properties, unknownAttributes, unknownElements)

    override fun fields(): ValueFields =
        ValueFields(
            "comment" to comment,
            "visible" to visible,
            "location" to location,
            "properties" to properties,
            "unknownAttributes" to unknownAttributes,
            "unknownElements" to unknownElements,
        )
}

/** Where RTSystemEditor draws an element. */
public class Location
@JvmOverloads
constructor(
    public val x: Int,
    public val y: Int,
    public val width: Int,
    public val height: Int,
    public val direction: String = "RIGHT",
) : ValueObject() {
    override fun fields(): ValueFields =
        ValueFields("x" to x, "y" to y, "width" to width, "height" to height, "direction" to direction)
}

/** An element outside the schema, kept as read: its name as written, attributes, children and text. */
public class ForeignElement
@JvmOverloads
constructor(
    public val name: String,
    public val attributes: Map<String, String> = emptyMap(),
    public val children: List<ForeignElement> = emptyList(),
    public val text: String = "",
) : ValueObject() {
    override fun fields(): ValueFields =
        ValueFields("name" to name, "attributes" to attributes, "children" to children, "text" to text)
}
