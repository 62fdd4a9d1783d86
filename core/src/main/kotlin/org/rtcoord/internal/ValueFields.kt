package org.rtcoord.internal

import org.rtcoord.InternalRtcoordApi

/**
 * The fields of a [org.rtcoord.ValueObject] by name, in declaration order: what its `equals`, `hashCode` and `toString`
 * are made of. Public for the dsl's values only.
 */
@InternalRtcoordApi
public class ValueFields(vararg fields: Pair<String, Any?>) {
    private val names = fields.map { it.first }
    private val values = fields.map { it.second }

    override fun equals(other: Any?): Boolean = other is ValueFields && values == other.values

    override fun hashCode(): Int = values.hashCode()

    override fun toString(): String = names.zip(values).joinToString(", ") { (name, value) -> "$name=$value" }
}
