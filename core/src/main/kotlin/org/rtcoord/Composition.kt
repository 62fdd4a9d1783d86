package org.rtcoord

/**
 * How a component stands in composite components, from its SDO organisations: a composite owns one
 * (whose members are its parts), a member belongs to one. A component that is neither is monolithic.
 */
public data class Composition(
    /** Whether the component owns an organisation: it is a composite component. */
    val isComposite: Boolean,
    /** Whether the component belongs to an organisation: it is part of a composite component. */
    val isMember: Boolean,
)
