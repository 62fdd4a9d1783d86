package org.rtcoord.internal.events

import org.rtcoord.LifeCycle
import org.rtcoord.RtcEvent

/** What a [ComponentWatch] asks its monitor to read, or do, after a batch of [WatchInput]s. */
internal sealed interface WatchStep {
    /** Nothing to read. */
    object Idle : WatchStep

    /** Carry out the registrations (whose read is a whole read). */
    object Reconfigure : WatchStep

    /** Read the whole component. */
    object ReadAll : WatchStep

    /** Read the states of the contexts [handles]. */
    class ReadStates(val handles: Set<Int>) : WatchStep

    /** Publish the held deactivation the last read confirmed, taking the hints come since first: see [ComponentWatch.settle]. */
    object Settle : WatchStep

    /** Take [states], which a probe read in read [stamp]. */
    class TakeStates(val states: Map<Int, LifeCycle>, val stamp: Long) : WatchStep
}

/** A batch's step, and the events it already decided. */
internal class WatchDecision(val step: WatchStep, val events: List<RtcEvent>)

/** What a read (or its failure) leads to. */
internal class WatchOutcome(
    val events: List<RtcEvent> = emptyList(),
    /** Timers to arm, each with the time `now` it fires at. */
    val timers: List<Pair<ComponentWatch.Timer, Long>> = emptyList(),
    /** Hints the reconciliation did not take: the next batch's. */
    val untaken: List<WatchInput.Hinted> = emptyList(),
    /** Read again at once: a hint that came during the read leads past what it found. */
    val readAgain: Boolean = false,
    /** What it changed of whether the component answers. */
    val changes: List<ComponentLiveness.Change> = emptyList(),
    /** The marker to send through the observer, if any. */
    val marker: String? = null,
)
