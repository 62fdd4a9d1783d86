package org.rtcoord.dsl.internal

/**
 * The selectors a script names components by: a name or path, a glob (`*_localise?`), or a glob narrowed to one type
 * (`* type=laser`, what `component(type = "laser")` writes): every component of that type, its profile's `type_name`. A
 * glob or a type covers several components, those that appear later included, where a rule's target may.
 */
internal object Selectors {
    private const val TYPE = " type="

    /** The selector of the components [name] names whose type is [type] (any type when null). */
    fun of(name: String, type: String?): String {
        if (type == null) return name
        require(type.isNotBlank() && type.none { it.isWhitespace() }) { "not a component type: '$type'" }
        return "$name$TYPE$type"
    }

    /** The name part of [selector]: what its name or path must match. */
    fun name(selector: String): String = selector.substringBefore(TYPE)

    /** The type [selector] asks for; null when any. */
    fun type(selector: String): String? = selector.substringAfter(TYPE, "").ifEmpty { null }

    /** Whether [selector] may cover several components: a glob, or a type. */
    fun isPattern(selector: String): Boolean = type(selector) != null || name(selector).any { it == '*' || it == '?' }
}
