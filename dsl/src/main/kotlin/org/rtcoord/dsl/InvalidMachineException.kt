package org.rtcoord.dsl

/**
 * A `modes { ... }` declaration that cannot run: a transition to an unknown mode, a mode no transition reaches, a
 * missing or wrong initial mode, a name used twice, a trigger without `goTo`, a network contradicting itself.
 * [problems] each name the mode and the reason; the message lists them all.
 */
public class InvalidMachineException
internal constructor(
    /** The machine's name. */
    public val machine: String,
    /** One line per problem. */
    public val problems: List<String>,
) : Exception("machine '$machine': ${problems.joinToString("; ")}")
