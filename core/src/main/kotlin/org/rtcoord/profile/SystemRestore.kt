package org.rtcoord.profile

import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/** What a restore did, kept as it was, and could not find. */
public class RestoreReport
@JvmOverloads
constructor(
    /** Changes made, one line each (`connected a:out to b:in`), components created first. */
    public val done: List<String>,
    /** Connections already there as the profile has them. */
    public val kept: List<String>,
    /** Optional components the system does not have, by path (none when missing components were created). */
    public val missingOptional: List<String>,
    /** The components created through their managers, by path. */
    public val created: List<String> = emptyList(),
    /**
     * Values written outside the constraint their component declares, one line each naming component, set and
     * parameter.
     */
    public val warnings: List<String> = emptyList(),
) : ValueObject() {
    /** This report with the components made for it, [created]. */
    @JvmSynthetic
    internal fun created(created: List<String>): RestoreReport =
        RestoreReport(done, kept, missingOptional, created, warnings)

    override fun fields(): ValueFields =
        ValueFields(
            "done" to done,
            "kept" to kept,
            "missingOptional" to missingOptional,
            "created" to created,
            "warnings" to warnings,
        )
}

/** A profile that cannot be applied as a whole; nothing was changed. */
public class ProfileRefusedException(
    /** Why, naming the component, port or value. */
    public val reason: String
) : Exception(reason)
