package org.rtcoord

/**
 * A call on something the caller closed: a tree, or a coordinator. Unchecked, as any use of a closed object is
 * (`IllegalStateException`); [subject] names what was closed.
 */
public class ClosedException(
    /** What was closed: `tree`, or a coordinator's name. */
    public val subject: String
) : IllegalStateException("$subject: closed")
