package org.rtcoord.internal.events

import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.UnreachableException

/**
 * What the tree believes of one watched component, when it says so and how it watches it: a pure state machine with no
 * clock and no I/O. Its [ComponentMonitor] feeds it what happened ([decide]: hints, ticks, timers, markers, watchdog
 * checks, registrations changed; then [read], [statesRead] or [failed] with what the read it asked for found,
 * [attached] and [detached] with how the observer's went), each with the time `now` in milliseconds of one monotonic
 * clock, and carries out what it returns, deciding nothing itself: the read or the observer's attachment to make
 * ([WatchStep]), the events to publish, the [Timer]s to arm (each for the time it fires at, on the same clock), the
 * marker to send, the timers and the method of its watching ([WatchOutcome]). How it is watched is its
 * [WatchArrangement]'s.
 *
 * Its lifecycle states, per execution context, are reconciled by [ContextStates], each context's by a [StateTracker]
 * standing in a [ContextPhase]; whether it answers by [ComponentLiveness]. The phases, what takes a context out of
 * each, and the timers they arm:
 *
 * |phase                                           |hints and reads                                                                                                                                                                                  |leaves when                                                                                                                                                                                                                                                                                        |to                                                         |
 * |------------------------------------------------|-------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------|---------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------------|-----------------------------------------------------------|
 * |[Agreed][ContextPhase.Agreed]                   |the last read found where the hints lead; a lifecycle hint taken since asks for its context's state                                                                                              |a read finds where the hints lead: a hinted deactivation (ACTIVE to INACTIVE) is held, anything else published; a read finds elsewhere                                                                                                                                                             |Held or Agreed; Leading (hints taken) or Disagreeing (none)|
 * |[Leading][ContextPhase.Leading]`(since)`        |hints lead to a state the reads since `since` did not find (OpenRTM-aist hints before the state shows)                                                                                           |[Timer.RECHECK] after 1, 2, 4... ms up to the grace period: a read finds where they lead; [Timer.GRACE] at `since` + the grace period: a read decides                                                                                                                                              |Held or Agreed; Agreed                                     |
 * |[Disagreeing][ContextPhase.Disagreeing]`(since)`|the read at `since` found what no hint announced                                                                                                                                                 |a hint, which may announce it; a read finds the state published; [Timer.GRACE]: a read decides                                                                                                                                                                                                     |Leading; Agreed; Agreed                                    |
 * |[Held][ContextPhase.Held]`(since, flushed)`     |a read confirmed a deactivation hinted at `since`, which an abort (INACTIVE then ERROR hinted) would look like until its ERROR hint is in; `flushed` once the marker sent after that read is back|the ERROR hint: a read confirms the abort (or finds the state not shown yet); [Timer.SETTLED] at `since` + [Timing.settleMillis], flushed: it is published as the confirming read found it ([settle]), hints come since taken first; [Timer.HOLD_LIMIT] at `since` + the hold limit: a read decides|Agreed (or Leading); Agreed; Agreed                        |
 *
 * An abort's ERROR hint leaves the component before the read that overtook it answered, on the connection its INACTIVE
 * hint came by: when the read is taken, it is already in this host's socket, waiting for the ORB's thread that reads
 * that connection, which under load may not get a core for milliseconds. So the marker goes out after the read, once
 * the ORB has handed on every message in its sockets, and through the ORB like a hint, so it comes back after them: it
 * waits as long as the ORB's threads are late, where a fixed time would not. A hold lasts at least
 * [Timing.settleMillis] from the INACTIVE hint's arrival besides, for a component on another host, whose two
 * connections are two flows.
 *
 * One timer of each kind is pending at a time; a timer that fires is reported by [WatchInput.Fired], with the time it
 * was armed for. A hold's timers are forgotten when the hold ends: one of them firing later is ignored, and the next
 * hold arms its own, so an earlier hold's limit never cuts a later hold short.
 */
internal class ComponentWatch(private val node: ComponentNode, now: Long, private val timing: Timing = DEFAULT_TIMING) {
    /** The machine's durations, in milliseconds. */
    class Timing(
        /** How long hints and reads may disagree before a read decides: hints late under load still count. */
        val graceMillis: Long = 500,
        /** The first wait before reading again while hints lead the read: their state shows a moment after them. */
        val firstRecheckMillis: Long = 1,
        /** How long a hinted deactivation may be held at most, waiting for its marker. */
        val holdLimitMillis: Long = 500,
        /** How long after its INACTIVE hint a deactivation is held at least, for an abort's ERROR hint to be taken. */
        val settleMillis: Long = 2,
    )

    /** The timers the monitor arms for the machine. */
    enum class Timer {
        RECHECK,
        GRACE,
        SETTLED,
        HOLD_LIMIT,
        /**
         * The grace period after the read that followed an observer's attachment: the states are read once more. A
         * transition under way as the observer was attached sent its hint to the observers the component had before
         * (none, or one detached since), and that read found the state it leaves; no hint would ever announce it.
         */
        CONFIRM,
    }

    private val states = ContextStates(node, timing.holdLimitMillis, timing.settleMillis)
    private val liveness = ComponentLiveness(now)
    private val arrangement = WatchArrangement()
    /**
     * The time each pending timer was armed for, by the timer's ordinal; [UNSET] when it is not. An array: a map of
     * timers weighed 24 bytes more in each watched component with no timer pending, and a boxed number per timer set.
     */
    private val deadlines = LongArray(Timer.entries.size) { UNSET }
    private var markers = 0L
    /** The wait of the latest [Timer.RECHECK] while hints lead the reads; 0 once they no longer do. */
    private var recheckDelay = 0L

    /** The marker on its way while a deactivation is held; null when none is. */
    private var marker: String? = null

    /** The last read, with the states the machine confirmed; null before the first. */
    var last: ComponentSnapshot? = null
        private set

    /** Counts the reads reconciled (and failures): a probe expecting an older one tells nothing new. */
    var epoch: Long = 0
        private set

    /** What the registrations ask for, as the monitor found them at the start of its batch. */
    var needs: WatchNeeds by arrangement::needs

    /** The states as the published events tell them, by context handle. */
    val published: Map<Int, LifeCycle>
        get() = states.published

    /** Whether hints and reads agree in every context, and no deactivation is held. */
    val agreed: Boolean
        get() = states.agreed

    /** Whether what the last read found is what a poll probe should expect: hints and reads agree, nothing held. */
    val settled: Boolean
        get() = needs.statesOnly && liveness.state == ComponentLiveness.State.ANSWERING && agreed

    /** Takes a batch of [inputs] at [now]; says what to read. */
    fun decide(inputs: List<WatchInput>, now: Long): WatchDecision {
        var readAll = false
        var reconfigure = false
        val handles = HashSet<Int>()
        var probed: WatchInput.Probed? = null
        var settle = false
        val events = ArrayList<RtcEvent>()
        val every = last?.contexts?.map { it.handle }.orEmpty()
        fun tick() {
            if (needs.statesOnly && liveness.state == ComponentLiveness.State.ANSWERING && every.isNotEmpty())
                handles += every
            else readAll = true
        }
        for (input in inputs) {
            when (input) {
                is WatchInput.Hinted -> readAll = take(input, now, handles) || readAll
                WatchInput.ReadWanted -> readAll = true
                WatchInput.Ticked,
                WatchInput.Unsettled -> tick()
                is WatchInput.Probed -> if (input.epoch == epoch) probed = input else tick()
                // A timer no longer waited for (an ended hold's) tells nothing.
                is WatchInput.Fired ->
                    if (deadlines[input.timer.ordinal] == input.at) {
                        deadlines[input.timer.ordinal] = UNSET
                        when (input.timer) {
                            Timer.RECHECK -> handles += every
                            Timer.GRACE -> if (states.disagreedSince != null) readAll = true
                            Timer.SETTLED -> settle = settle || (states.held.isNotEmpty() && marker == null)
                            Timer.HOLD_LIMIT -> if (states.held.isNotEmpty()) readAll = true
                            Timer.CONFIRM -> handles += every
                        }
                    }
                is WatchInput.MarkerBack ->
                    if (input.marker == marker) {
                        marker = null
                        states.flushed()
                        settle = settle || states.held.any { now - it.since >= timing.settleMillis }
                    }
                is WatchInput.Overdue -> if (overdue(input, now, events)) tick()
                WatchInput.Reconfigured -> reconfigure = true
            }
        }
        val step =
            when {
                liveness.state == ComponentLiveness.State.FINALIZED -> WatchStep.Idle
                reconfigure -> arrangement.reconfigured()
                readAll -> WatchStep.ReadAll
                handles.isNotEmpty() ->
                    if (last == null || liveness.state != ComponentLiveness.State.ANSWERING) WatchStep.ReadAll
                    else WatchStep.ReadStates(handles)
                settle -> WatchStep.Settle
                else -> probed?.let { WatchStep.TakeStates(it.states, it.stamp) } ?: WatchStep.Idle
            }
        return WatchDecision(step, events)
    }

    /** [WatchStep.Attach] ended in [attachment] at [now]: an observer attached, its silence counts from then. */
    fun attached(attachment: Attachment, now: Long): WatchOutcome {
        if (attachment is Attachment.Attached) liveness.hinted(now)
        return WatchOutcome(arranged = arrangement.attached(attachment, liveness.state))
    }

    /** [WatchStep.Detach] was carried out: the observer, if any, is detached. */
    fun detached(): WatchOutcome = WatchOutcome(arranged = arrangement.detached(liveness.state, last?.advertised))

    /** A whole read found [snapshot] at [now]; [late] are the hints that came meanwhile. */
    fun read(snapshot: ComponentSnapshot, now: Long, late: List<WatchInput.Hinted>): WatchOutcome {
        val events = ArrayList<RtcEvent>()
        val changes = liveness.answered(now)
        val recovered = ComponentLiveness.Change.Recovered in changes
        if (recovered) events += Recovered(node)
        val afterAttaching = arrangement.rereading
        // Before reconciling: a component back may have dropped its observer, and until one is attached anew no hint
        // announces what this read finds.
        val arranged = arrangement.answered(recovered, liveness.state, snapshot.advertised)
        val previous = last
        val reconciled = reconcile(previous, snapshot, now, late, confirm = afterAttaching)
        events += reconciled.events
        if (previous != null) events += differences(node, previous, snapshot)
        last = snapshot
        epoch++
        return WatchOutcome(
            events,
            reconciled.timers,
            reconciled.untaken,
            reconciled.readAgain,
            changes,
            reconciled.marker,
            arranged,
        )
    }

    /**
     * A read of the states alone found [found] (by handle) at [now]; [late] are the hints that came meanwhile.
     * [published] is what the tree shows of the component since: kept instead of an equal copy, as the last read is
     * kept as long as the watch lives, beside the tree's own.
     */
    fun statesRead(
        found: Map<Int, LifeCycle>,
        now: Long,
        late: List<WatchInput.Hinted>,
        published: ComponentSnapshot? = null,
    ): WatchOutcome {
        val previous = last ?: return WatchOutcome(untaken = late)
        liveness.answered(now)
        val snapshot =
            previous
                .withStates { found[it.handle] }
                .let { read -> if (read !== previous && published == read) published else read }
        last = snapshot
        epoch++
        return reconcile(snapshot, snapshot, now, late)
    }

    /**
     * Reconciles again at [now] with what the last read found, [late] hints first: a held deactivation that has settled
     * is published without reading again, as the hold waited for hints, not for the component, and a hint come
     * meanwhile (an abort's ERROR) is taken before.
     */
    fun settle(now: Long, late: List<WatchInput.Hinted>): WatchOutcome {
        val snapshot = last ?: return WatchOutcome(untaken = late)
        return reconcile(snapshot, snapshot, now, late)
    }

    /** A read failed at [now] with [cause]; a silence shorter than the interval it should speak at is no news. */
    fun failed(cause: RtcException, now: Long): WatchOutcome {
        epoch++
        val unreachable = cause is UnreachableException
        val beatMillis = arrangement.expectedInterval?.inWholeMilliseconds
        val changes =
            liveness.failed(
                now,
                gone = unreachable && cause.cause is org.omg.CORBA.OBJECT_NOT_EXIST,
                unreachable = unreachable,
                beatMillis,
            )
        val events =
            if (ComponentLiveness.Change.Finalized in changes) {
                listOf(ComponentFinalized(node))
            } else {
                changes.map { change ->
                    if (change is ComponentLiveness.Change.Lost) HeartbeatLost(node, change.silentMillis)
                    else BecameZombie(node, cause)
                }
            }
        return WatchOutcome(events, changes = changes, arranged = arrangement.failed(changes, liveness.state))
    }

    /**
     * Takes a hint in at [now]. A lifecycle hint adds its context's handle to [handles] (reading that state is enough);
     * returns whether anything else calls for reading the whole component.
     */
    private fun take(hinted: WatchInput.Hinted, now: Long, handles: MutableSet<Int>): Boolean {
        val hint = hinted.hint
        liveness.hinted(now, finalize = hint.isFinalize)
        return when {
            hint.isHeartbeat || hint.kind == HintKind.OTHER -> false
            // The read this asks for finds the component gone, and it is finalized.
            hint.isFinalize -> true
            hint.kind == HintKind.RTC_STATUS -> states.hinted(hint, hinted.at)?.also { handles += it } == null
            else -> true
        }
    }

    /**
     * The watchdog's check: a read probes a component whose beat is overdue, and one silent past the limit is lost. The
     * read is a poll tick's, its states alone when that is all the registrations want: heartbeats late under load (ten
     * thousand components on one connection) made whole reads, whose load made more heartbeats late. One that does not
     * answer is probed at its heartbeat by the poll its [arrangement] keeps for it, not at every check (ten a beat).
     */
    private fun overdue(input: WatchInput.Overdue, now: Long, events: MutableList<RtcEvent>): Boolean {
        liveness.hinted(input.heardAt)
        if (liveness.state != ComponentLiveness.State.ANSWERING) return false
        liveness.checked(now, arrangement.silenceLimit?.inWholeMilliseconds)?.let {
            events += HeartbeatLost(node, it.silentMillis)
        }
        // A process that died refuses the read at once: that is known a beat after its last, not at the limit.
        val beat = arrangement.heartbeat?.inWholeMilliseconds ?: return false
        return now - liveness.lastHeard >= beat + beat / OVERDUE_FRACTION
    }

    /**
     * Reconciles each context's state in [snapshot] with the hints, [late] ones first; arms what the phases call for.
     */
    private fun reconcile(
        previous: ComponentSnapshot?,
        snapshot: ComponentSnapshot,
        now: Long,
        late: List<WatchInput.Hinted>,
        confirm: Boolean = false,
    ): WatchOutcome {
        val untaken = ArrayList<WatchInput.Hinted>()
        var taken = false
        for (hinted in late) {
            val hint = hinted.hint
            // Hints that came during the read tell of changes made before it answered: an abort's ERROR, say.
            if (hint.kind == HintKind.RTC_STATUS && !hint.isFinalize && states.hinted(hint, hinted.at) != null) {
                liveness.hinted(now)
                taken = true
            } else {
                untaken += hinted
            }
        }
        val events = states.read(previous, snapshot, now, timing.graceMillis, hintsExpected = arrangement.observed)
        val timers = ArrayList<Pair<Timer, Long>>()
        fun arm(timer: Timer, after: Long) {
            if (deadlines[timer.ordinal] != UNSET) return
            val at = now + after.coerceAtLeast(0)
            deadlines[timer.ordinal] = at
            timers += timer to at
        }
        // A late hint may lead past what the read found: read again now rather than after the grace period.
        val readAgain = taken && states.disagreedSince != null
        // One grace read at a time: disagreements that began later end later, and the read deciding the oldest arms the
        // next.
        states.disagreedSince?.let { arm(Timer.GRACE, it + timing.graceMillis - now) }
        recheckIfHintsLead(::arm)
        if (confirm) {
            // The latest attachment's confirmation replaces an earlier one's, due before it.
            deadlines[Timer.CONFIRM.ordinal] = UNSET
            arm(Timer.CONFIRM, timing.graceMillis)
        }
        val held = states.held
        if (held.isEmpty()) {
            // A marker sent for a hold that is over is no longer awaited, and the hold's timers end with it.
            marker = null
            HOLD_TIMERS.forEach { deadlines[it.ordinal] = UNSET }
        } else {
            val since = held.minOf { it.since }
            arm(Timer.HOLD_LIMIT, since + timing.holdLimitMillis - now)
            arm(Timer.SETTLED, since + timing.settleMillis - now)
        }
        // Each read that leaves a hold waiting for its hints sends a marker of its own: an older one tells nothing of
        // what came since.
        return WatchOutcome(
            events,
            timers,
            untaken,
            readAgain,
            marker = if (held.any { !it.flushed }) newMarker() else null,
        )
    }

    /**
     * Reads the states again soon while hints lead the read, at growing intervals up to the grace period: OpenRTM-aist
     * sends a transition's hints before its new state shows (its state machine updates the state once the actions that
     * send them are done), so a read made at once may find the old one.
     */
    private fun recheckIfHintsLead(arm: (Timer, Long) -> Unit) {
        if (!states.hintsLead) {
            recheckDelay = 0
            return
        }
        if (deadlines[Timer.RECHECK.ordinal] != UNSET) return
        recheckDelay =
            if (recheckDelay == 0L) timing.firstRecheckMillis else minOf(recheckDelay * 2, timing.graceMillis)
        arm(Timer.RECHECK, recheckDelay)
    }

    /** A new marker, to be sent through the observer now: it comes back once the hints waiting before it are taken. */
    private fun newMarker(): String = "$MARKER_PREFIX${++markers}".also { marker = it }

    /** The services the component offers observers, as it lists them. */
    private val ComponentSnapshot.advertised: String?
        get() = properties["sdo.service.consumer.available_services"]

    companion object {
        /** What every marker begins with: a hint that does is a marker, and nothing else. */
        const val MARKER_PREFIX: String = "rtcoord-marker-"

        /** A beat is overdue a tenth of it late: heartbeats come on time to within a few milliseconds. */
        private const val OVERDUE_FRACTION = 10

        /** A timer's deadline while it is not set. */
        private const val UNSET = Long.MIN_VALUE

        /** The timers of a hold, which end with it. */
        private val HOLD_TIMERS = setOf(Timer.SETTLED, Timer.HOLD_LIMIT)
    }
}

/** The timing of every watch but tests': one for all, as ten thousand watches would each keep a copy. */
private val DEFAULT_TIMING = ComponentWatch.Timing()
