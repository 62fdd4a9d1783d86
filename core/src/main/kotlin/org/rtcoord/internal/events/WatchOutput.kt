package org.rtcoord.internal.events

import kotlin.time.Duration
import org.rtcoord.LifeCycle
import org.rtcoord.RtcEvent
import org.rtcoord.WatchMethod

/** What a [ComponentWatch] asks its monitor to read, or do, next. */
internal sealed interface WatchStep {
    /** Nothing to read. */
    object Idle : WatchStep

    /** Read the whole component. */
    object ReadAll : WatchStep

    /** Read the states of the contexts [handles]. */
    class ReadStates(val handles: Set<Int>) : WatchStep

    /**
     * Publish the held deactivation the last read confirmed, taking the hints come since first: see
     * [ComponentWatch.settle].
     */
    object Settle : WatchStep

    /** Take [states], which a probe read in read [stamp]. */
    class TakeStates(val states: Map<Int, LifeCycle>, val stamp: Long) : WatchStep

    /**
     * Attach an observer of a flavour among [advertised] (the component's `sdo.service.consumer.available_services`)
     * that sends heartbeats every [heartbeat] and traffic hints at most every [traffic]; then tell
     * [ComponentWatch.attached].
     */
    class Attach(val advertised: String?, val heartbeat: Duration, val traffic: Duration) : WatchStep

    /** Detach the observer, if one is attached; then tell [ComponentWatch.detached]. */
    object Detach : WatchStep

    /** Forget the observer without asking the component: it is gone. */
    object Drop : WatchStep
}

/** A batch's step, and the events it already decided. */
internal class WatchDecision(val step: WatchStep, val events: List<RtcEvent>)

/** What a read (or its failure), an attachment or a detachment leads to. */
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
    /** What it changed of how the component is watched, with the step to carry out next. */
    val arranged: Arranged = Arranged.NOTHING,
)

/** What a [WatchArrangement] decided: the [next] step, and what the monitor sets up before it. */
internal data class Arranged(
    /** The step to carry out at once, after the rest. */
    val next: WatchStep = WatchStep.Idle,
    /** The timers to set, when they change. */
    val schedule: WatchSchedule? = null,
    /** How the component is watched, when that was decided: told to whoever has not been told yet. */
    val method: WatchMethod? = null,
    /**
     * It stopped answering: the managers hosting it are asked whether they still answer, every [askManagersEvery] once
     * found dead.
     */
    val askManagersEvery: Duration? = null,
) {
    companion object {
        /** Nothing arranged. */
        val NOTHING: Arranged = Arranged()
    }
}

/** How often a component is polled ([pollPeriod]) and the heartbeat its watchdog expects ([heartbeat]); null: none. */
internal data class WatchSchedule(val pollPeriod: Duration?, val heartbeat: Duration?) {
    companion object {
        /** Neither polled nor watched. */
        val OFF: WatchSchedule = WatchSchedule(null, null)
    }
}
