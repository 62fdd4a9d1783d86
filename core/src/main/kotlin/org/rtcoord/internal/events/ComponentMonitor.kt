package org.rtcoord.internal.events

import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.async
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.PortTraffic
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.UnreachableException
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMode
import org.rtcoord.internal.TreeCore
import org.slf4j.LoggerFactory
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.TimeUnit
import java.util.concurrent.TimeoutException
import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.seconds

/**
 * Watches one component for every registration interested in it, with one pipeline whatever the
 * source: an observer hint, a poll tick or a liveness check only asks the monitor to read the component
 * again; events are the differences between consecutive reads, lifecycle states reconciled with the
 * hints per execution context ([ContextStates]). One coroutine does all of it, in order, so the
 * component's events come out in the order they happened; delivery to handlers is the sinks' job. What
 * has states of its own lives apart: whether it answers ([ComponentLiveness]), its observer
 * ([ObserverLink]), its timers ([MonitorTimers]) and how it is watched ([decideWatchMethod]).
 *
 * Over 300 lines: the order in which hints, reads and timers are taken is one piece of logic, kept whole.
 */
internal class ComponentMonitor(
    private val core: TreeCore,
    private val host: ObserverHost,
    val node: ComponentNode,
    private val ended: (ComponentMonitor) -> Unit,
) {
    private sealed interface Work
    private class Received(val hint: Hint) : Work
    private object Read : Work
    /** A poll tick; [done] tells the tree's [PollSchedule] once it has been served. */
    private class Tick(val done: () -> Unit) : Work
    private object Liveness : Work
    /** A poll read its [StateProbe] could not finish alone. */
    private class Probed(val outcome: StateProbe.Outcome) : Work
    /** Time to read the states again: the hints lead the last read. */
    private object Recheck : Work
    /** The grace period of the oldest disagreement between hints and reads is over: a read decides. */
    private object GraceOver : Work
    /** A held deactivation has settled: a read decides, once the hints sent before it are in too. */
    private object Settled : Work
    /** A [HintMarker]'s marker came back through the observer. */
    private class Marked(val hint: Hint) : Work
    /** Registrations changed; [done] completes once the monitor watches as they ask. */
    private class Reconfigure(val done: CompletableDeferred<Unit>? = null) : Work

    /** [item], sent to this monitor's work once a delay is over; one at a time, owned by the worker coroutine. */
    private inner class DelayedWork(private val item: Work) {
        /** Whether it was sent and has not [arrived] yet. */
        var isPending = false
            private set

        /** Sends it in [after] milliseconds. */
        fun send(after: Long) {
            isPending = true
            core.scope.launch { delay(after); work.trySend(item) }
        }

        /** The worker took it. */
        fun arrived() {
            isPending = false
        }
    }

    private val log = LoggerFactory.getLogger(ComponentMonitor::class.java)
    private val subject = node.path.toString()
    private val registrations = CopyOnWriteArrayList<MonitorRegistration>()
    private val work = Channel<Work>(Channel.UNLIMITED)

    /** How the component is watched, once decided; set through [Watcher.announce]. */
    @Volatile var method: WatchMethod? = null

    // Owned by the worker coroutine.
    private var last: ComponentSnapshot? = null
    private val states = ContextStates(node, HOLD_LIMIT_MILLIS, SETTLE_MILLIS)
    /** While a deactivation is held: when the hints sent before the read that confirmed it are in. */
    private val marker = HintMarker(subject)
    /** The wait of the latest [Recheck] while hints lead the reads; 0 once they no longer do. */
    private var recheckDelay = 0L
    /** The [Recheck] on its way: reads made meanwhile do not ask for another. */
    private val recheck = DelayedWork(Recheck)
    /** The [GraceOver] on its way. */
    private val graceOver = DelayedWork(GraceOver)
    /** The [Settled] on its way. */
    private val settled = DelayedWork(Settled)
    private val liveness = ComponentLiveness(now())
    private val link = ObserverLink(core, host, subject, node.component)
    private var attachment: Attachment = Attachment.NotTried
    /** The traffic interval the observer was attached with. */
    private var attachedTraffic: Duration? = null
    /** Work that arrived during a read, other than the lifecycle hints taken at once: the next round's. */
    private val carried = ArrayList<Work>()
    /** Counts the reads this monitor reconciled (and failures): a probe sent before the latest one tells nothing new. */
    private var epoch = 0L
    private val probe: StateProbe? = core.requests.takeIf { it.supports(node.component.ref) }?.let { requests ->
        StateProbe(requests, node.component.ref, node.component::stamp, { timers.heard() }) { outcome -> if (!work.trySend(Probed(outcome)).isSuccess) outcome.done() }
    }
    private val member = object : PollSchedule.Member {
        override fun tick(done: () -> Unit) {
            if (!work.trySend(Tick(done)).isSuccess) done()
        }

        override fun probe(done: () -> Unit): Boolean = probe?.send(done) ?: false

        override fun late() {
            probe?.late()
        }
    }
    private val timers = MonitorTimers(core, member) { work.trySend(Liveness) }

    init {
        // On the dispatcher of remote calls, which its reads then make without changing threads.
        core.scope.launch(core.remote.dispatcher) { run() }
    }

    /** Adds [registration] and returns once the component was read and, if asked for, observed. */
    suspend fun add(registration: MonitorRegistration) {
        registrations += registration
        val ready = CompletableDeferred<Unit>()
        if (work.trySend(Reconfigure(ready)).isSuccess) ready.await()
    }

    /** Removes [registration]; returns whether none is left (the caller then [stop]s the monitor). */
    fun remove(registration: MonitorRegistration): Boolean {
        registrations -= registration
        work.trySend(Reconfigure())
        return registrations.isEmpty()
    }

    /** Stops watching: polling ends and the observer is detached, soon, by the monitor's coroutine. */
    fun stop() {
        work.close()
    }

    private val stopped = CompletableFuture<Unit>()

    /**
     * Waits, at most [timeout], until the monitor's coroutine has finished (its observer detached), on
     * the calling thread: the tree is closing. Call [stop] first.
     */
    fun awaitStopped(timeout: Duration) {
        val done = runCatching { stopped.get(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS) }
        if (done.exceptionOrNull() is TimeoutException) log.warn("{}: observer not detached within {}", subject, timeout)
    }

    private suspend fun run() {
        try {
            while (true) {
                val batch = ArrayList(carried).also { carried.clear() }
                if (batch.isEmpty()) batch += work.receiveCatching().getOrNull() ?: break
                while (true) batch += work.tryReceive().getOrNull() ?: break
                handle(batch)
            }
        } finally {
            withContext(NonCancellable) {
                timers.stop()
                probe?.close()
                link.detach()
                ended(this@ComponentMonitor)
                stopped.complete(Unit)
            }
        }
    }

    private suspend fun handle(batch: List<Work>) {
        var read = false
        val hintedStates = HashSet<Int>()
        var probed: StateProbe.Outcome.Changed? = null
        val reconfigurations = batch.filterIsInstance<Reconfigure>()
        fun tick() {
            if (registrations.all { it.statesOnly } && liveness.state == ComponentLiveness.State.ANSWERING) hintedStates += node.component.contexts.keys else read = true
        }
        for (item in batch) {
            when (item) {
                is Received -> read = take(item.hint, hintedStates) || read
                Read -> read = true
                Recheck -> {
                    recheck.arrived()
                    hintedStates += node.component.contexts.keys
                }
                GraceOver -> {
                    graceOver.arrived()
                    if (states.awaitingConfirmation) read = true
                }
                is Tick -> tick()
                is Probed -> when (val outcome = item.outcome) {
                    // Read as this monitor last knew it: the states it found are news.
                    is StateProbe.Outcome.Changed -> if (outcome.epoch == epoch) probed = outcome else tick()
                    is StateProbe.Outcome.Unsettled -> tick()
                }
                // The hints sent before the held read are in: a fresh read of the states decides, once settled.
                is Marked -> if (marker.cameBack(item.hint)) {
                    states.flushed()
                    if (states.settlesIn(now()) == 0L) hintedStates += node.component.contexts.keys
                }
                Settled -> {
                    settled.arrived()
                    if (states.holding && !marker.isPending) hintedStates += node.component.contexts.keys
                }
                Liveness -> read = checkLiveness() || read
                is Reconfigure -> Unit
            }
        }
        try {
            when {
                liveness.state == ComponentLiveness.State.FINALIZED -> return
                reconfigurations.isNotEmpty() -> reconfigure()
                read -> readAndPublish()
                hintedStates.isNotEmpty() -> readStates(hintedStates)
                probed != null -> takeStates(probed.states, probed.stamp)
            }
        } finally {
            // Before the ticks are done: the probe of the next one expects what this batch found.
            expectProbes()
            reconfigurations.forEach { it.done?.complete(Unit) }
            batch.forEach { item ->
                when (item) {
                    is Tick -> item.done()
                    is Probed -> item.outcome.done()
                    else -> Unit
                }
            }
        }
    }

    /**
     * Tells the probe what its reads should find, when a read finding that needs nothing of this monitor:
     * every registration wants states alone, the component answers, and its hints and reads agree.
     */
    private fun expectProbes() {
        val probe = probe ?: return
        val settled = registrations.isNotEmpty() && registrations.all { it.statesOnly } &&
            liveness.state == ComponentLiveness.State.ANSWERING && !states.awaitingConfirmation && !states.holding
        probe.expect(last?.takeIf { settled }?.let { StateProbe.Expectation.of(it, node.component.contexts, epoch) })
    }

    /**
     * Takes a hint in. A lifecycle hint adds its context's handle to [hintedStates] (reading that state
     * is enough); returns whether anything else calls for reading the whole component.
     */
    private fun take(hint: Hint, hintedStates: MutableSet<Int>): Boolean {
        liveness.hinted(now(), finalize = hint.isFinalize)
        return when {
            hint.isHeartbeat || hint.kind == HintKind.OTHER -> false
            // The read this asks for finds the component gone, and it is finalized.
            hint.isFinalize -> true
            hint.kind == HintKind.RTC_STATUS -> states.hinted(hint)?.also { hintedStates += it } == null
            else -> true
        }
    }

    /** Reads only the states of the contexts [handles] and reconciles them with the hints. */
    private suspend fun readStates(handles: Set<Int>) {
        val previous = last ?: return readAndPublish()
        val contexts = node.component.contexts
        // Only a whole read brings a silent or unreachable component back, observer and all.
        if (handles.any { it !in contexts } || liveness.state != ComponentLiveness.State.ANSWERING) return readAndPublish()
        suspend fun state(handle: Int) = LifeCycle.of(core.remote.call(subject, "get_component_state") { contexts.getValue(handle).get_component_state(node.component.ref) })
        val stamp = node.component.stamp()
        val states = try {
            // One context, the common case, is read without a coroutine per read.
            handles.singleOrNull()?.let { mapOf(it to state(it)) }
                ?: coroutineScope { handles.associateWith { async { state(it) } }.mapValues { it.value.await() } }
        } catch (e: RtcException) {
            failed(e)
            return
        }
        takeStates(states, stamp)
    }

    /** Takes [states], just read by context handle by the read stamped [stamp], as the component's and publishes what changed. */
    private fun takeStates(states: Map<Int, LifeCycle>, stamp: Long) {
        val previous = last ?: return
        liveness.answered(now())
        // Onto the component's latest snapshot, not this monitor's: an operation may have published a newer one since.
        node.component.publishStates(states, stamp)
        val snapshot = previous.copy(contexts = previous.contexts.map { context -> states[context.handle]?.let { context.copy(state = it) } ?: context })
        last = snapshot
        epoch++
        publish(stateEvents(snapshot))
    }

    /** Reconciles each context's state in [snapshot] with its tracker; schedules a re-read where hints and reads disagree. */
    private fun stateEvents(snapshot: ComponentSnapshot): List<RtcEvent> {
        val late = takeLateStateHints()
        val events = states.read(last, snapshot, now(), GRACE_MILLIS, hintsExpected = link.observer != null)
        if (states.awaitingConfirmation) {
            // A late hint may lead past what the read found: read again now rather than after the grace period.
            if (late) carried += Read
            decideAfterGrace()
        }
        recheckIfHintsLead()
        when {
            !states.holding -> marker.forget()
            // A deactivation this read confirmed is held until the hints sent before the read are in.
            !marker.isPending -> {
                marker.send(link.observer)
                core.scope.launch { delay(HOLD_LIMIT_MILLIS); work.trySend(Read) }
            }
        }
        states.settlesIn(now())?.let { if (!settled.isPending) settled.send(after = it) }
        return events
    }

    /**
     * Asks for the read that decides the oldest disagreement between hints and reads, due when its grace
     * period is over. One is pending at a time: disagreements that began later end later, and the read that
     * decides the oldest asks for the next.
     */
    private fun decideAfterGrace() {
        val since = states.disagreedSince ?: return
        if (!graceOver.isPending) graceOver.send(after = (since + GRACE_MILLIS - now()).coerceAtLeast(0))
    }

    /**
     * Reads the states again soon while hints lead the read, at growing intervals up to the grace period:
     * OpenRTM-aist sends a transition's hints before its new state shows (its state machine updates the
     * state once the actions that send them are done), so a read made at once may find the old one.
     */
    private fun recheckIfHintsLead() {
        if (!states.hintsLead) {
            recheckDelay = 0
            return
        }
        if (recheck.isPending) return
        recheckDelay = if (recheckDelay == 0L) FIRST_RECHECK_MILLIS else minOf(recheckDelay * 2, GRACE_MILLIS)
        recheck.send(after = recheckDelay)
    }

    /**
     * Takes the lifecycle hints that arrived while the component was being read, before reconciling: they
     * tell of changes made before it answered. An abort hints INACTIVE then ERROR, and when a reset follows
     * at once, a read between the two finds INACTIVE, which the first hint alone would confirm as a
     * deactivation. Returns whether there were any.
     */
    private fun takeLateStateHints(): Boolean {
        var taken = false
        while (true) {
            val item = work.tryReceive().getOrNull() ?: return taken
            val hint = (item as? Received)?.hint
            if (hint != null && hint.kind == HintKind.RTC_STATUS && !hint.isFinalize && states.hinted(hint) != null) {
                liveness.hinted(now())
                taken = true
            } else {
                carried += item
            }
        }
    }

    /** Whether the component must be read: it is probed while unreachable, and read once it went silent, which is announced. */
    private fun checkLiveness(): Boolean {
        liveness.hinted(timers.heardAt)
        if (liveness.state == ComponentLiveness.State.UNREACHABLE) return true
        val limit = pushRegistration()?.options?.takeIf { link.observer != null }?.let { it.heartbeat * it.missedBeats }
        val lost = liveness.checked(now(), limit?.inWholeMilliseconds) ?: return false
        publish(listOf(HeartbeatLost(node, lost.silentMillis)))
        return true
    }

    private suspend fun reconfigure() {
        if (registrations.isEmpty()) {
            timers.stop()
            link.detach()
            return
        }
        readAndPublish()
        if (liveness.state == ComponentLiveness.State.FINALIZED) return
        val push = pushRegistration()
        // Asking for data hints (or no longer) takes an observer attached with the new interval.
        if (link.observer != null && attachedTraffic != trafficInterval()) link.detach()
        if (push != null && link.observer == null) {
            attachment = if (liveness.state == ComponentLiveness.State.UNREACHABLE) {
                Attachment.Failed("it does not answer")
            } else {
                val traffic = trafficInterval()
                link.attach(last?.properties?.get("sdo.service.consumer.available_services"), push.options.heartbeat, traffic, ::received).also {
                    if (it is Attachment.Attached) {
                        liveness.hinted(now())
                        timers.heard()
                        attachedTraffic = traffic
                    }
                }
            }
            // A change between that read and the attachment sent its hint to nobody: read once more.
            if (link.observer != null) readAndPublish()
        }
        val method = decideWatchMethod(registrations.map { it.options }, attachment)
        timers.poll(method?.pollPeriod)
        if (method != null) {
            if (method != this.method) log.debug("{}: watched by {}", subject, method)
            core.watcher.announce(this, method, registrations)
        }
        timers.watch(push?.options?.heartbeat)
    }

    /**
     * What the observer received. A heartbeat only says when (see [MonitorTimers]); data flowing changes
     * nothing a read would show, and goes straight to the registrations that asked for [PortTraffic].
     */
    private fun received(hint: Hint) {
        val traffic = hint.traffic()
        when {
            marker.isMarker(hint) -> work.trySend(Marked(hint))
            hint.isHeartbeat -> timers.heard()
            traffic != null -> {
                timers.heard()
                val event = PortTraffic(node, traffic.first, traffic.second)
                core.model.publish(listOf(event)) { registrations.forEach { registration -> if (registration.traffic) registration.sink.offer(it) } }
            }
            else -> work.trySend(Received(hint))
        }
    }

    /** The shortest traffic interval a push registration that wants traffic asks for; an hour (next to none) when none does. */
    private fun trafficInterval(): Duration =
        registrations.filter { it.traffic && it.options.mode != WatchMode.POLL }.minOfOrNull { it.options.trafficInterval } ?: NO_TRAFFIC

    private fun pushRegistration(): MonitorRegistration? =
        registrations.filter { it.options.mode != WatchMode.POLL }.minByOrNull { it.options.heartbeat }

    private suspend fun readAndPublish() {
        val snapshot = try {
            node.component.refresh(subject)
            if (registrations.any { it.configuration } && node.component.snapshot.value?.configuration == null) {
                node.component.loadConfiguration(subject)
            }
            node.component.snapshot.value!!
        } catch (e: RtcException) {
            failed(e)
            return
        }
        val events = mutableListOf<RtcEvent>()
        if (liveness.answered(now()).isNotEmpty()) {
            log.info("{}: answers again", subject)
            events += Recovered(node)
            // The component may have dropped an observer it could not reach, or restarted without it.
            link.detach()
            if (pushRegistration() != null) work.trySend(Reconfigure())
        }
        val previous = last
        events += stateEvents(snapshot)
        if (previous != null) events += differences(node, previous, snapshot)
        last = snapshot
        epoch++
        publish(events)
    }

    private fun failed(e: RtcException) {
        epoch++
        val unreachable = e is UnreachableException
        val changes = liveness.failed(now(), gone = unreachable && e.cause is org.omg.CORBA.OBJECT_NOT_EXIST, unreachable = unreachable)
        if (ComponentLiveness.Change.Finalized in changes) {
            log.info("{}: finalized", subject)
            timers.stop()
            link.drop()
            publish(listOf(ComponentFinalized(node)))
            return
        }
        if (changes.isEmpty()) return
        log.info("{}; probing until it answers again", e.message)
        publish(changes.map { change -> if (change is ComponentLiveness.Change.Lost) HeartbeatLost(node, change.silentMillis) else BecameZombie(node, e) })
        // Keep probing while unreachable, even when only the observer watched it.
        if (timers.pollPeriod == null) timers.poll(pushRegistration()?.options?.heartbeat)
        // Its manager may have died with it, and with every other component it hosted.
        core.watcher.componentSilent(node, timers.pollPeriod ?: 1.seconds)
    }

    /** Where the registrations' events go. */
    fun sinks(): List<EventSink> = registrations.map { it.sink }

    /** Publishes [events] through the tree's model, with the states they leave the component in. */
    private fun publish(events: List<RtcEvent>) {
        core.model.publish(events, node.component, states.published) { event -> registrations.forEach { it.sink.offer(event) } }
    }

    private companion object {
        /** How long hints and reads may disagree before a read decides: hints late under load still count. */
        const val GRACE_MILLIS = 500L

        /** The first wait before reading again when hints lead the read: their state shows a moment after them. */
        const val FIRST_RECHECK_MILLIS = 1L

        /** How long a hinted deactivation may wait for its [HintMarker]: as long as hints and reads may disagree. */
        const val HOLD_LIMIT_MILLIS = GRACE_MILLIS

        /**
         * How long a hinted deactivation is held at least, for an abort's ERROR hint that its marker may
         * overtake: a few of the scheduler's time slices on a busy machine.
         */
        const val SETTLE_MILLIS = 10L

        /** The traffic interval asked for when nobody wants traffic: OpenRTM sends data hints every second by default. */
        val NO_TRAFFIC = 1.hours

        fun now(): Long = MonitorTimers.now()
    }
}
