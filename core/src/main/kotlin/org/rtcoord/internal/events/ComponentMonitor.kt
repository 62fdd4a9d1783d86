package org.rtcoord.internal.events

import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.Job
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
import org.rtcoord.EventOptions
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.PortTraffic
import org.rtcoord.Recovered
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.StateChanged
import org.rtcoord.UnreachableException
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged
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
 * hints by a [StateTracker] per execution context. One coroutine does all of it, in order, so the
 * component's events come out in the order they happened; delivery to handlers is the sinks' job.
 *
 * It is longer than most files here because it is where reads, hints, timers and the observer meet, in
 * that one coroutine. What has states of its own lives apart and is tested alone: whether the component
 * answers ([ComponentLiveness]), its lifecycle per context ([StateTracker]), its observer
 * ([ObserverLink]) and how it is watched ([decideWatchMethod]).
 */
internal class ComponentMonitor(
    private val core: TreeCore,
    private val host: ObserverHost,
    val node: ComponentNode,
    private val ended: (ComponentMonitor) -> Unit,
) {
    /**
     * One registration's needs: [configuration] when it wants configuration events, [statesOnly] when it
     * wants nothing but lifecycle and liveness events (then a poll tick reads only the states), [traffic]
     * when it asked for [PortTraffic] by name (data hints are many: nobody gets them without asking).
     */
    class Registration(val sink: EventSink, val options: EventOptions, val configuration: Boolean, val statesOnly: Boolean, val traffic: Boolean = false) {
        /** How the component is watched, as this registration was last told; owned by the monitor's coroutine. */
        var told: WatchMethod? = null
    }

    private sealed interface Work
    private class Received(val hint: Hint) : Work
    private object Read : Work
    private object Tick : Work
    private object Liveness : Work
    /** Registrations changed; [done] completes once the monitor watches as they ask. */
    private class Reconfigure(val done: CompletableDeferred<Unit>? = null) : Work

    private val log = LoggerFactory.getLogger(ComponentMonitor::class.java)
    private val subject = node.path.toString()
    private val registrations = CopyOnWriteArrayList<Registration>()
    private val work = Channel<Work>(Channel.UNLIMITED)

    /** How the component is watched, once decided; set through [Watcher.announce]. */
    @Volatile var method: WatchMethod? = null

    // Owned by the worker coroutine.
    private var last: ComponentSnapshot? = null
    private val trackers = HashMap<Int, StateTracker>()
    private val liveness = ComponentLiveness(now())
    private val link = ObserverLink(core, host, subject, node.component)
    private var attachment: Attachment = Attachment.NotTried
    /** The traffic interval the observer was attached with. */
    private var attachedTraffic: Duration? = null
    private var poller: Job? = null
    private var pollPeriod: Duration? = null
    private var watchdog: Job? = null

    init {
        core.scope.launch { run() }
    }

    /** Adds [registration] and returns once the component was read and, if asked for, observed. */
    suspend fun add(registration: Registration) {
        registrations += registration
        val ready = CompletableDeferred<Unit>()
        if (work.trySend(Reconfigure(ready)).isSuccess) ready.await()
    }

    /** Removes [registration]; returns whether none is left (the caller then [stop]s the monitor). */
    fun remove(registration: Registration): Boolean {
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
        try {
            stopped.get(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS)
        } catch (e: TimeoutException) {
            log.warn("{}: observer not detached within {}", subject, timeout)
        }
    }

    private suspend fun run() {
        try {
            for (first in work) {
                val batch = mutableListOf(first)
                while (true) batch += work.tryReceive().getOrNull() ?: break
                handle(batch)
            }
        } finally {
            withContext(NonCancellable) {
                poller?.cancel()
                watchdog?.cancel()
                link.detach()
                ended(this@ComponentMonitor)
                stopped.complete(Unit)
            }
        }
    }

    private suspend fun handle(batch: List<Work>) {
        var read = false
        val hintedStates = HashSet<Int>()
        val reconfigurations = batch.filterIsInstance<Reconfigure>()
        // Ticks that queued up behind a slow read are served by one read: all but one were missed.
        val ticks = batch.count { it === Tick }
        if (ticks > 1) core.missedPollTicks.addAndGet(ticks - 1L)
        for (item in batch) {
            when (item) {
                is Received -> read = take(item.hint, hintedStates) || read
                Read -> read = true
                Tick -> if (registrations.all { it.statesOnly } && liveness.state == ComponentLiveness.State.ANSWERING) hintedStates += node.component.contexts.keys else read = true
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
            }
        } finally {
            reconfigurations.forEach { it.done?.complete(Unit) }
        }
    }

    /**
     * Takes a hint in. A lifecycle hint adds its context's handle to [hintedStates] (reading that state
     * is enough); returns whether anything else calls for reading the whole component.
     */
    private fun take(hint: Hint, hintedStates: MutableSet<Int>): Boolean {
        liveness.hinted(now(), finalize = hint.isFinalize)
        // Data flowing changes nothing a read would show.
        hint.traffic()?.let { (port, outgoing) ->
            val event = PortTraffic(node, port, outgoing)
            registrations.filter { it.traffic }.forEach { it.sink.offer(event) }
            return false
        }
        when {
            hint.kind == HintKind.HEARTBEAT || hint.kind == HintKind.EC_HEARTBEAT || hint.kind == HintKind.OTHER -> return false
            // The read this asks for finds the component gone, and it is finalized.
            hint.isFinalize -> Unit
            hint.kind == HintKind.RTC_STATUS -> {
                // A hint that names no state, or a context the component is not known to be in, is no
                // transition: only reading the component tells what, if anything, happened.
                val (state, handle) = hint.lifeCycle() ?: return true
                val tracker = trackers[handle] ?: return true
                tracker.hint(state)
                hintedStates += handle
                return false
            }
        }
        return true
    }

    /** Reads only the states of the contexts [handles] and reconciles them with the hints. */
    private suspend fun readStates(handles: Set<Int>) {
        val previous = last ?: return readAndPublish()
        val contexts = node.component.contexts
        // Only a whole read brings a silent or unreachable component back, observer and all.
        if (handles.any { it !in contexts } || liveness.state != ComponentLiveness.State.ANSWERING) return readAndPublish()
        val states = try {
            coroutineScope {
                handles.associateWith { handle ->
                    async { LifeCycle.of(core.remote.call(subject, "get_component_state") { contexts.getValue(handle).get_component_state(node.component.ref) }) }
                }.mapValues { it.value.await() }
            }
        } catch (e: RtcException) {
            failed(e)
            return
        }
        liveness.answered(now())
        val snapshot = previous.copy(contexts = previous.contexts.map { context -> states[context.handle]?.let { context.copy(state = it) } ?: context })
        node.component.publish(snapshot)
        last = snapshot
        publish(stateEvents(snapshot))
    }

    /** Reconciles each context's state in [snapshot] with its tracker; schedules a re-read where hints and reads disagree. */
    private fun stateEvents(snapshot: ComponentSnapshot): List<RtcEvent> {
        val previous = last
        val events = mutableListOf<RtcEvent>()
        for (context in snapshot.contexts) {
            val tracker = trackers.getOrPut(context.handle) { StateTracker(previous?.context(context.handle)?.state ?: context.state) }
            tracker.reconcile(context.state, now(), GRACE_MILLIS, hintsExpected = link.observer != null).forEach { (from, to) -> events += StateChanged(node, context.handle, from, to) }
        }
        trackers.keys.retainAll(snapshot.contexts.map { it.handle }.toSet())
        if (trackers.values.any { it.awaitingConfirmation }) {
            core.scope.launch {
                delay(GRACE_MILLIS)
                work.trySend(Read)
            }
        }
        return events
    }

    /** Whether the component must be read: it is probed while unreachable, and read once it went silent, which is announced. */
    private fun checkLiveness(): Boolean {
        if (liveness.state == ComponentLiveness.State.UNREACHABLE) return true
        val limit = pushRegistration()?.options?.takeIf { link.observer != null }?.let { it.heartbeat * it.missedBeats }
        val lost = liveness.checked(now(), limit?.inWholeMilliseconds) ?: return false
        publish(listOf(HeartbeatLost(node, lost.silentMillis)))
        return true
    }

    private suspend fun reconfigure() {
        if (registrations.isEmpty()) {
            poller?.cancel().also { poller = null; pollPeriod = null }
            watchdog?.cancel().also { watchdog = null }
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
                link.attach(last?.properties?.get("sdo.service.consumer.available_services"), push.options.heartbeat, traffic) { hint -> work.trySend(Received(hint)) }
                    .also { if (it is Attachment.Attached) { liveness.hinted(now()); attachedTraffic = traffic } }
            }
            // A change between that read and the attachment sent its hint to nobody: read once more.
            if (link.observer != null) readAndPublish()
        }
        val method = decideWatchMethod(registrations.map { it.options }, attachment)
        schedulePolling(method?.pollPeriod)
        announce(method)
        watchdog?.cancel()
        watchdog = push?.let { core.scope.launchTicks(it.options.heartbeat / 2) { work.trySend(Liveness) } }
    }

    private fun schedulePolling(period: Duration?) {
        if (period == pollPeriod) return
        poller?.cancel()
        pollPeriod = period
        poller = period?.let { core.scope.launchTicks(it) { work.trySend(Tick) } }
    }

    /** The shortest traffic interval a push registration that wants traffic asks for; an hour (next to none) when none does. */
    private fun trafficInterval(): Duration =
        registrations.filter { it.traffic && it.options.mode != WatchMode.POLL }.minOfOrNull { it.options.trafficInterval } ?: NO_TRAFFIC

    private fun pushRegistration(): Registration? =
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
        publish(events)
    }

    private fun failed(e: RtcException) {
        val unreachable = e is UnreachableException
        val changes = liveness.failed(now(), gone = unreachable && e.cause is org.omg.CORBA.OBJECT_NOT_EXIST, unreachable = unreachable)
        if (ComponentLiveness.Change.Finalized in changes) {
            log.info("{}: finalized", subject)
            poller?.cancel()
            watchdog?.cancel()
            link.drop()
            publish(listOf(ComponentFinalized(node)))
            return
        }
        if (changes.isEmpty()) return
        log.info("{}; probing until it answers again", e.message)
        publish(changes.map { change -> if (change is ComponentLiveness.Change.Lost) HeartbeatLost(node, change.silentMillis) else BecameZombie(node, e) })
        // Keep probing while unreachable, even when only the observer watched it.
        if (poller == null) schedulePolling(pushRegistration()?.options?.heartbeat)
        // Its manager may have died with it, and with every other component it hosted.
        core.watcher.componentSilent(node, pollPeriod ?: 1.seconds)
    }

    /** Tells each registration not yet told, and the tree's reporters when it changed, how the component is watched. */
    private fun announce(method: WatchMethod?) {
        if (method == null) return
        if (method != this.method) log.debug("{}: watched by {}", subject, method)
        core.watcher.announce(this, method)
        for (registration in registrations) {
            if (registration.told == method) continue
            registration.sink.offer(WatchMethodChanged(node, registration.told, method))
            registration.told = method
        }
    }

    /** Where the registrations' events go. */
    fun sinks(): List<EventSink> = registrations.map { it.sink }

    private fun publish(events: List<RtcEvent>) {
        if (events.isEmpty()) return
        for (registration in registrations) events.forEach(registration.sink::offer)
    }

    private companion object {
        /** How long hints and reads may disagree before a read decides: hints late under load still count. */
        const val GRACE_MILLIS = 500L

        /** The traffic interval asked for when nobody wants traffic: OpenRTM sends data hints every second by default. */
        val NO_TRAFFIC = 1.hours

        fun now(): Long = System.nanoTime() / 1_000_000
    }
}
