package org.rtcoord.dsl

/**
 * One name [LiveCheck] reports: [at] where the script writes it (`file:line:col`), [name] as written, and what it
 * found: why it is missing, where the script creates it, or what was written instead of a name.
 */
public class NameFinding
internal constructor(
    /** Where the script writes it, as `file:line:col`. */
    public val at: String,
    /** The name as the script writes it; for what could not be checked, the expression written. */
    public val name: String,
    /** What was found: a reason, or where the script creates it. */
    public val says: String,
) {
    override fun toString(): String = "$at: $name: $says"
}

/**
 * What [LiveCheck] found of a script: the names the live system lacks ([missing], an error each), the names missing now
 * that the script creates itself ([created]: a manager's `create` of a type gives `TYPE<n>`), and what it could not
 * check ([unchecked]: names the script computes as it runs).
 */
public class ScriptCheck
internal constructor(
    /** The names the live system lacks, in the order they are written. */
    public val missing: List<NameFinding>,
    /**
     * The parameters and configuration sets that what the script names lacks: a rule on the parameter can never fire, a
     * mode that asks for the set never has its network; each also in [missing]. (A rule on a port that is not there
     * stops the coordinator's start.)
     */
    public val cannotFire: List<NameFinding>,
    /** Names missing now that the script creates, `says` naming where. */
    public val created: List<NameFinding>,
    /** The names the script computes, which only running it tells. */
    public val unchecked: List<NameFinding>,
)
