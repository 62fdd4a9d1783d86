package org.rtcoord

import org.rtcoord.internal.ValueFields

/**
 * How a component stands in composite components, from its SDO organisations: a composite owns one (whose members are
 * its parts), a member belongs to one. A component that is neither is monolithic.
 */
public class Composition(
    /** Whether the component owns an organisation: it is a composite component. */
    public val isComposite: Boolean,
    /** Whether the component belongs to an organisation: it is part of a composite component. */
    public val isMember: Boolean,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("isComposite" to isComposite, "isMember" to isMember)
}
