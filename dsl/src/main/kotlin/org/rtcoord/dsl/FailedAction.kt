@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl

import org.rtcoord.InternalRtcoordApi
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/**
 * An action of the coordinator that failed: [action] as the log wrote it, [reason] as the system answered, and whether
 * it was a best effort ([Reaction.attempt]), after which its handler went on.
 */
public class FailedAction(
    public val action: String,
    public val reason: String,
    @get:JvmName("isBestEffort") public val bestEffort: Boolean,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("action" to action, "reason" to reason, "bestEffort" to bestEffort)
}
