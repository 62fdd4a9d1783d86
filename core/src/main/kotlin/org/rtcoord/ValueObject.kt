package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * A value of the API (a snapshot, an event, a profile's element, a port's sample): equal to another of the same class
 * whose fields are equal, and hashed by its fields, as a data class would be; printed as `Name(field=value, ...)`
 * unless the class says otherwise. Values are not data classes: a data class's `componentN` and `copy` tie every
 * compiled caller to its list of fields, so that a new field would break them; these gain fields compatibly.
 */
public abstract class ValueObject @InternalRtcoordApi protected constructor() {
    /**
     * The fields that make the value, by name, in declaration order. Synthetic: Java sees neither this nor rtcoord's
     * internal [ValueFields].
     */
    @JvmSynthetic protected abstract fun fields(): ValueFields

    // The same object is equal without its fields made: a StateFlow compares every value it is handed with the one it
    // holds, as often as a rule fires.
    final override fun equals(other: Any?): Boolean =
        other === this || (other is ValueObject && other.javaClass == javaClass && fields() == other.fields())

    final override fun hashCode(): Int = fields().hashCode()

    override fun toString(): String = "${javaClass.simpleName}(${fields()})"
}
