package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * How a component stands in composite components, from its SDO organisations: a composite owns one
 * (whose members are its parts), a member belongs to one. A component that is neither is monolithic.
 */
public class Composition(
    /** Whether the component owns an organisation: it is a composite component. */
    public val isComposite: Boolean,
    /** Whether the component belongs to an organisation: it is part of a composite component. */
    public val isMember: Boolean,
) {
    private fun fields() = ValueFields("Composition", "isComposite" to isComposite, "isMember" to isMember)
    override fun equals(other: Any?): Boolean = other is Composition && fields() == other.fields()
    override fun hashCode(): Int = fields().hashCode()
    override fun toString(): String = fields().toString()
}
