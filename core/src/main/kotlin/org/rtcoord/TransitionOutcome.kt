package org.rtcoord

/**
 * How an activation, deactivation or reset ended: the state the component reached, and whether it got there only after
 * its execution context had given up waiting. OpenRTM-aist's synchronous transitions wait `transition_timeout` (0.5 s
 * by default) for the new state and then answer `RTC_ERROR`, while the callback (`on_activated`, `on_deactivated`,
 * `on_reset`, or an `on_execute` the context thread is busy in) runs on; rtcoord then reads the state until the
 * operation's own deadline, and a state that arrives is a success, a slow one. Only the tree makes one: the class is
 * sealed for the reason [Node] gives.
 */
public sealed class TransitionOutcome(
    /** The state the component is in now, the one the operation leads to. */
    public val state: LifeCycle,
    /**
     * What the context answered when the component was not there yet (`RTC_ERROR`, or `no answer` when the call
     * outlasted its deadline); null when it answered `RTC_OK`.
     */
    public val lateAnswer: String?,
    /** From the call to the read that found [state], in milliseconds. */
    public val elapsedMillis: Long,
) {
    /** Whether the component reached [state] only after its context had answered that it did not. */
    @get:JvmName("isSlow")
    public val slow: Boolean
        get() = lateAnswer != null

    /** `ACTIVE`, or `ACTIVE, slow: the context answered RTC_ERROR, the state arrived after 812 ms`. */
    override fun toString(): String =
        if (lateAnswer == null) state.name
        else "$state, slow: the context answered $lateAnswer, the state arrived after $elapsedMillis ms"
}

/** The [TransitionOutcome]s the tree makes. */
internal class TransitionOutcomeImpl(state: LifeCycle, lateAnswer: String?, elapsedMillis: Long) :
    TransitionOutcome(state, lateAnswer, elapsedMillis)
