package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * How one component is watched: the part of its [ComponentWatch] that decides whether an observer is attached, detached
 * or attached anew, at which period the component is polled (and probed while it does not answer), whose heartbeats the
 * watchdog expects, and the [org.rtcoord.WatchMethod] that says so. Pure: the machine tells it what the reads and
 * attachments found, and returns what it decides as [Arranged] for the monitor to carry out.
 *
 * It arranges in stages, each ending in a step the monitor carries out at once:
 *
 * |stage  |entered when                                                                                                                                                             |next step                                                                                                                                                                                   |then                                               |
 * |-------|-------------------------------------------------------------------------------------------------------------------------------------------------------------------------|--------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------|---------------------------------------------------|
 * |OBSERVE|the registrations changed, after a whole read ([reconfigured]); a read brought the component back ([answered]): it may have dropped its observer, or restarted without it|[WatchStep.Detach] an observer that is stale or sends other traffic than asked for; else [WatchStep.Attach] one if a push registration wants it and the component answers; else settle      |OBSERVE after detaching, REREAD after attaching one|
 * |REREAD |an observer was attached ([attached])                                                                                                                                    |[WatchStep.ReadAll]: a change between the last read and the attachment sent its hint to nobody (the machine reads the states once more a grace period later, [ComponentWatch.Timer.CONFIRM])|settle                                             |
 * |none   |settled, or the component is finalized                                                                                                                                   |nothing: reads arrange nothing more                                                                                                                                                         |                                                   |
 *
 * Settling decides the method ([decideWatchMethod]), the poll period and the heartbeat watched ([WatchSchedule]), and
 * ends the stages. Whatever the stage: a component found unreachable is probed at its heartbeat if nothing polls it,
 * and the managers hosting it are asked ([Arranged.askManagersEvery]); a finalized one has its observer dropped
 * ([WatchStep.Drop]) and its timers stopped; one that nobody watches any more has its observer detached and its timers
 * stopped.
 */
internal class WatchArrangement {
    private enum class Stage {
        OBSERVE,
        REREAD,
    }

    /** What the registrations ask for, as the monitor last found them. */
    var needs: WatchNeeds = WatchNeeds.NONE

    private var stage: Stage? = null
    private var attachment: Attachment = Attachment.NotTried

    /** What the attached observer was asked for; null when none is attached. */
    private var observer: Observer? = null

    /** The component came back since its observer was attached: it may have dropped it. */
    private var stale = false

    /** The timers as last arranged. */
    private var schedule = WatchSchedule.OFF

    /** Whether the next whole read is the one that follows an observer's attachment ([Stage.REREAD]). */
    val rereading: Boolean
        get() = stage == Stage.REREAD

    /** Whether an observer announces the component's changes, so that its hints are awaited. */
    val observed: Boolean
        get() = observer != null && !stale

    /** The heartbeat the attached observer was asked for; null when none is attached or none pushes. */
    val heartbeat: Duration?
        get() = observer?.heartbeat?.takeIf { needs.push != null }

    /** How long the attached observer may be silent before the component is lost; null when [heartbeat] is. */
    val silenceLimit: Duration?
        get() = heartbeat?.let { beat -> needs.push?.let { beat * it.missedBeats } }

    /** How often the component should give a sign of life: its heartbeat when observed, else its poll period. */
    val expectedInterval: Duration?
        get() = heartbeat ?: schedule.pollPeriod

    /** The registrations changed: the step that starts arranging anew. */
    fun reconfigured(): WatchStep {
        if (needs.options.isEmpty()) {
            stage = null
            return WatchStep.Detach
        }
        stage = Stage.OBSERVE
        return WatchStep.ReadAll
    }

    /**
     * A whole read answered, the component standing at [answers] after it; [recovered] when it brought the component
     * back; [advertised] is its `sdo.service.consumer.available_services`.
     */
    fun answered(recovered: Boolean, answers: ComponentLiveness.State, advertised: String?): Arranged {
        if (recovered) {
            // Even one attached just now, before the read that found the component back (it was silent).
            stale = observer != null
            stage = Stage.OBSERVE
        }
        return proceed(answers, advertised)
    }

    /** A read failed, leaving the component at [answers] with [changes]. */
    fun failed(changes: List<ComponentLiveness.Change>, answers: ComponentLiveness.State): Arranged {
        if (ComponentLiveness.Change.Finalized in changes) {
            stage = null
            observer = null
            schedule = WatchSchedule.OFF
            return Arranged(WatchStep.Drop, schedule)
        }
        if (ComponentLiveness.Change.Unreachable !in changes) return proceed(answers, null)
        // Probed until it answers again, even when only the observer watched it; its manager may have died with it.
        schedule = WatchSchedule(schedule.pollPeriod ?: needs.heartbeat, schedule.heartbeat)
        val askManagersEvery = schedule.pollPeriod ?: 1.seconds
        return proceed(answers, null).copy(schedule = schedule, askManagersEvery = askManagersEvery)
    }

    /** The observer was detached, as [WatchStep.Detach] asked; the component stands at [answers]. */
    fun detached(answers: ComponentLiveness.State, advertised: String?): Arranged {
        observer = null
        stale = false
        if (needs.options.isEmpty()) {
            schedule = WatchSchedule.OFF
            return Arranged(schedule = schedule)
        }
        return proceed(answers, advertised)
    }

    /** [WatchStep.Attach] ended in [result]; the component stands at [answers]. */
    fun attached(result: Attachment, answers: ComponentLiveness.State): Arranged {
        attachment = result
        if (result !is Attachment.Attached) return settle(answers)
        observer = needs.heartbeat?.let { Observer(needs.traffic, it) }
        stage = Stage.REREAD
        return Arranged(WatchStep.ReadAll)
    }

    private fun proceed(answers: ComponentLiveness.State, advertised: String?): Arranged {
        val push = needs.push
        return when {
            stage == null -> Arranged.NOTHING
            answers == ComponentLiveness.State.FINALIZED -> Arranged.NOTHING.also { stage = null }
            stage == Stage.REREAD -> settle(answers)
            observer.let { it != null && (stale || it.differs(needs)) } -> Arranged(WatchStep.Detach)
            push == null || observer != null -> settle(answers)
            answers == ComponentLiveness.State.UNREACHABLE -> {
                attachment = Attachment.Failed("it does not answer")
                settle(answers)
            }
            else -> Arranged(WatchStep.Attach(advertised, needs.heartbeat!!, needs.traffic))
        }
    }

    private fun settle(answers: ComponentLiveness.State): Arranged {
        stage = null
        val method = decideWatchMethod(needs.options, attachment, heartbeat)
        // An unreachable component stays probed, whatever else watches it.
        val probe = needs.heartbeat?.takeIf { answers == ComponentLiveness.State.UNREACHABLE }
        schedule = WatchSchedule(method?.pollPeriod ?: probe, heartbeat ?: needs.heartbeat)
        return Arranged(schedule = schedule, method = method)
    }

    /** The traffic interval and heartbeat an attached observer was asked for. */
    private class Observer(val traffic: Duration, val heartbeat: Duration) {
        /** Whether [needs] ask for another: the observer is attached anew. */
        fun differs(needs: WatchNeeds): Boolean =
            traffic != needs.traffic || (needs.heartbeat != null && heartbeat != needs.heartbeat)
    }
}
