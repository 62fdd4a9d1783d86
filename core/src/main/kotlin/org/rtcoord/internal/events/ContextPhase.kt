package org.rtcoord.internal.events

/**
 * Where the reconciliation of one execution context's lifecycle hints and reads stands: the phase of its
 * [StateTracker]. How each phase is entered and left, and which of [ComponentWatch]'s timers it arms, is the table in
 * [ComponentWatch]'s KDoc.
 */
internal sealed interface ContextPhase {
    /** The last read found where the hints lead; hints taken since wait for the read they asked for. */
    object Agreed : ContextPhase

    /** Hints and reads have disagreed since the read at [since]: a read once the grace period is over decides. */
    sealed interface Unconfirmed : ContextPhase {
        val since: Long
    }

    /** Hints lead to a state the reads since [since] have not found: OpenRTM-aist hints before the state shows. */
    data class Leading(override val since: Long) : Unconfirmed

    /** The read at [since] found a change no hint announced: its hints may be on their way. */
    data class Disagreeing(override val since: Long) : Unconfirmed

    /**
     * A read confirmed a deactivation hinted at [since], which an abort (INACTIVE then ERROR hinted) would look like
     * until its ERROR hint is in; [flushed] once the marker sent after that read came back, so every hint sent before
     * it has been taken.
     */
    data class Held(val since: Long, val flushed: Boolean) : ContextPhase
}
