package org.rtcoord.internal

/**
 * A public value class's fields by name: its `equals`, `hashCode` and `toString` as a data class would
 * have them. The API has no data classes, since their `componentN` and `copy` tie every compiled caller
 * to the list of fields, and a new field would break them.
 */
internal class ValueFields(private val type: String, vararg fields: Pair<String, Any?>) {
    private val names = fields.map { it.first }
    private val values = fields.map { it.second }

    override fun equals(other: Any?): Boolean = other is ValueFields && type == other.type && values == other.values

    override fun hashCode(): Int = values.hashCode()

    override fun toString(): String = names.zip(values).joinToString(", ", "$type(", ")") { (name, value) -> "$name=$value" }
}
