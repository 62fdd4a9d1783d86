package org.rtcoord.internal

import org.rtcoord.InternalRtcoordApi

/**
 * The fields of a [org.rtcoord.ValueObject] by name, in declaration order: what its `equals`, `hashCode` and `toString`
 * are made of. Public for the dsl's values only.
 *
 * Compared field by field, stopping at the first that differs, and hashed as the list of its values is: a StateFlow
 * compares each value it is handed with the one it holds, as often as a rule fires.
 */
@InternalRtcoordApi
public class ValueFields(private vararg val fields: Pair<String, Any?>) {
    override fun equals(other: Any?): Boolean {
        if (other !is ValueFields || other.fields.size != fields.size) return false
        return fields.indices.all { fields[it].second == other.fields[it].second }
    }

    override fun hashCode(): Int = fields.fold(1) { hash, field -> 31 * hash + (field.second?.hashCode() ?: 0) }

    override fun toString(): String = fields.joinToString(", ") { (name, value) -> "$name=$value" }
}
