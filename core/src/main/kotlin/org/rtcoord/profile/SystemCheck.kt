package org.rtcoord.profile

import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/** One way the live system differs from a profile. */
public class ProfileDifference(
    /** The component, port or connection concerned. */
    public val subject: String,
    /** What the profile has. */
    public val expected: String,
    /** What the system has. */
    public val actual: String,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("subject" to subject, "expected" to expected, "actual" to actual)

    override fun toString(): String = "$subject: expected $expected, found $actual"
}
