package org.rtcoord.profile

import org.rtcoord.LifeCycle
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/** Starting (activating) or stopping (deactivating) a system in the order of its profile. */
public enum class OrderedAction(
    @get:JvmSynthetic internal val ordering: OrderingKind,
    /** The state the action brings components to: ACTIVE for [START], INACTIVE for [STOP]. */
    public val reaches: LifeCycle,
) {
    /** Activation, in the order of the profile's Activation block. */
    START(OrderingKind.ACTIVATION, LifeCycle.ACTIVE),

    /** Deactivation, in the order of the profile's Deactivation block. */
    STOP(OrderingKind.DEACTIVATION, LifeCycle.INACTIVE),
}

/**
 * One step of an ordered start or stop: act on [component]'s context [contextId] once every step of a lower [sequence]
 * is done and [condition] holds.
 */
public class PlannedStep(
    public val sequence: Int,
    public val component: String,
    public val contextId: Int,
    public val condition: Condition,
) : ValueObject() {
    override fun fields(): ValueFields =
        ValueFields(
            "sequence" to sequence,
            "component" to component,
            "contextId" to contextId,
            "condition" to condition,
        )

    override fun toString(): String =
        "$sequence $component context $contextId" +
            when (condition) {
                Condition.None -> ""
                is Condition.WaitTime -> " after waiting ${condition.milliseconds} ms"
                is Condition.Preceding ->
                    " after ${condition.components.joinToString { it.instanceName }} (${condition.sendingTiming}" +
                        (if (condition.timeoutMillis > 0) ", timeout ${condition.timeoutMillis} ms)" else ")")
            }
}

/**
 * What became of one step: done (and when, from the start of the run; [detail] says if it was slow), failed (why) or
 * not done (why).
 */
public class StepOutcome(
    public val step: PlannedStep,
    public val done: Boolean,
    public val atMillis: Long,
    public val detail: String,
) : ValueObject() {
    override fun fields(): ValueFields =
        ValueFields("step" to step, "done" to done, "atMillis" to atMillis, "detail" to detail)

    override fun toString(): String =
        if (done) "done at $atMillis ms: $step" + detail.ifEmpty { null }?.let { " ($it)" }.orEmpty()
        else "NOT done: $step: $detail"
}
