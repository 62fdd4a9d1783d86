package org.rtcoord.internal.events

import _SDOPackage.NameValue
import _SDOPackage.SDOServiceHelper
import _SDOPackage.ServiceProfile
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.Job
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.async
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.EventOptions
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.ObserverFlavour
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
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * Watches one component for every registration interested in it, with one pipeline whatever the
 * source: an observer hint, a poll tick or a liveness check only asks the monitor to read the component
 * again; events are the differences between consecutive reads, lifecycle states reconciled with the
 * hints by a [StateTracker] per execution context. One coroutine does all of it, in order, so the
 * component's events come out in the order they happened; delivery to handlers is the sinks' job.
 */
internal class ComponentMonitor(
    private val core: TreeCore,
    private val host: ObserverHost,
    val node: ComponentNode,
    private val ended: (ComponentMonitor) -> Unit,
) {
    /**
     * One registration's needs: [configuration] when it wants configuration events, [statesOnly] when it
     * wants nothing but lifecycle and liveness events (then a poll tick reads only the states).
     */
    class Registration(val sink: EventSink, val options: EventOptions, val configuration: Boolean, val statesOnly: Boolean) {
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
    @Volatile private var lastSign = TimeSource.Monotonic.markNow()

    /** How the component is watched, once decided; set through [Watcher.announce]. */
    @Volatile var method: WatchMethod? = null

    // Owned by the worker coroutine.
    private var last: ComponentSnapshot? = null
    private val trackers = HashMap<Int, StateTracker>()
    private var observer: ObserverHost.Observer? = null
    private var attachment: Attachment = Attachment.NotTried
    private var poller: Job? = null
    private var pollPeriod: Duration? = null
    private var watchdog: Job? = null
    private var suspect = false
    private var dead = false
    private var finalizing = false
    private var finished = false

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
                detach()
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
                Tick -> if (registrations.all { it.statesOnly } && !dead) hintedStates += node.component.contexts.keys else read = true
                Liveness -> read = checkLiveness() || read
                is Reconfigure -> Unit
            }
        }
        try {
            when {
                finished -> return
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
        lastSign = TimeSource.Monotonic.markNow()
        when {
            hint.kind == HintKind.HEARTBEAT || hint.kind == HintKind.EC_HEARTBEAT || hint.kind == HintKind.OTHER -> return false
            hint.isFinalize -> finalizing = true
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
        if (handles.any { it !in contexts }) return readAndPublish()
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
        lastSign = TimeSource.Monotonic.markNow()
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
            tracker.reconcile(context.state, now(), GRACE_MILLIS, hintsExpected = observer != null).forEach { (from, to) -> events += StateChanged(node, context.handle, from, to) }
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

    /** Whether the component has been silent too long; announces it, and asks for a read to decide. */
    private fun checkLiveness(): Boolean {
        if (dead) return true
        val push = pushRegistration() ?: return false
        val silent = lastSign.elapsedNow()
        if (observer == null || suspect || silent <= push.options.heartbeat * push.options.missedBeats) return false
        suspect = true
        publish(listOf(HeartbeatLost(node, silent.inWholeMilliseconds)))
        return true
    }

    private suspend fun reconfigure() {
        if (registrations.isEmpty()) {
            poller?.cancel().also { poller = null; pollPeriod = null }
            watchdog?.cancel().also { watchdog = null }
            detach()
            return
        }
        readAndPublish()
        if (finished) return
        if (pushRegistration() != null && observer == null) {
            attachment = if (dead) Attachment.Failed("it does not answer") else attach()
            // A change between that read and the attachment sent its hint to nobody: read once more.
            if (observer != null) readAndPublish()
        }
        val method = decideWatchMethod(registrations.map { it.options }, attachment)
        schedulePolling(method?.pollPeriod)
        announce(method)
        val push = pushRegistration()
        watchdog?.cancel()
        watchdog = push?.let { registration ->
            core.scope.launch {
                while (isActive) {
                    delay(registration.options.heartbeat / 2)
                    work.trySend(Liveness)
                }
            }
        }
    }

    private fun schedulePolling(period: Duration?) {
        if (period == pollPeriod) return
        poller?.cancel()
        pollPeriod = period
        poller = period?.let {
            core.scope.launch {
                // Ticks at a fixed rate: a slow read does not push the next tick back.
                val start = TimeSource.Monotonic.markNow()
                var tick = 1L
                while (isActive) {
                    delay(it * tick.toDouble() - start.elapsedNow())
                    tick++
                    work.trySend(Tick)
                }
            }
        }
    }

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
        lastSign = TimeSource.Monotonic.markNow()
        val events = mutableListOf<RtcEvent>()
        if (dead || suspect) {
            log.info("{}: answers again", subject)
            events += Recovered(node)
            dead = false
            suspect = false
            // The component may have dropped an observer it could not reach, or restarted without it.
            detach()
            if (pushRegistration() != null) work.trySend(Reconfigure())
        }
        val previous = last
        events += stateEvents(snapshot)
        if (previous != null) events += differences(node, previous, snapshot)
        last = snapshot
        publish(events)
    }

    private fun failed(e: RtcException) {
        val gone = e is UnreachableException && e.cause is org.omg.CORBA.OBJECT_NOT_EXIST
        if (gone || (finalizing && e is UnreachableException)) {
            log.info("{}: finalized", subject)
            finished = true
            poller?.cancel()
            watchdog?.cancel()
            observer?.close()
            observer = null
            publish(listOf(ComponentFinalized(node)))
            return
        }
        if (dead) return
        dead = true
        log.info("{}; probing until it answers again", e.message)
        val events = mutableListOf<RtcEvent>()
        if (!suspect) events += HeartbeatLost(node, lastSign.elapsedNow().inWholeMilliseconds)
        events += BecameZombie(node, e)
        publish(events)
        // Keep probing while dead, even when only the observer watched it.
        if (poller == null) schedulePolling(pushRegistration()?.options?.heartbeat)
        // Its manager may have died with it, and with every other component it hosted.
        core.watcher.componentSilent(node, pollPeriod ?: 1.seconds)
    }

    /** Attaches an observer of a flavour the component advertises (either, when it lists none); says how that went. */
    private suspend fun attach(): Attachment {
        val push = pushRegistration() ?: return Attachment.NotTried
        val advertised = last?.properties?.get("sdo.service.consumer.available_services")
            ?.split(',')?.map { it.trim() }?.filter { it.isNotEmpty() }
        val flavours = ObserverFlavour.values().filter { advertised == null || it.repositoryId in advertised }
        if (flavours.isEmpty()) return Attachment.NotOffered(advertised.orEmpty())
        val configuration = try {
            core.remote.call(subject, "get_configuration") { node.component.ref.get_configuration() }
        } catch (e: RtcException) {
            return Attachment.Failed("get_configuration: ${e.reason}")
        }
        removeStaleObservers(core, subject, node.component.ref, configuration)
        val seconds = (push.options.heartbeat.inWholeMilliseconds / 1000.0).toString()
        var failure: String? = null
        for (flavour in flavours) {
            val candidate = host.observer(flavour) { hint -> work.trySend(Received(hint)) }
            val properties = mapOf(
                "observed_status" to "ALL",
                "heartbeat.enable" to "YES", "heartbeat.interval" to seconds,
                "rtc_heartbeat.enable" to "YES", "rtc_heartbeat.interval" to seconds,
            ).map { (name, value) -> NameValue(name, core.orb.orb.create_any().apply { insert_string(value) }) }
            val profile = ServiceProfile(candidate.profileId, flavour.repositoryId, properties.toTypedArray(), SDOServiceHelper.unchecked_narrow(candidate.reference))
            val accepted = try {
                core.remote.call(subject, "add_service_profile") { configuration.add_service_profile(profile) }
            } catch (e: RtcException) {
                failure = failure ?: "add_service_profile (${flavour.label}): ${e.reason}"
                false
            }
            if (accepted) {
                observer = candidate
                lastSign = TimeSource.Monotonic.markNow()
                return Attachment.Attached(flavour)
            }
            candidate.close()
        }
        return failure?.let(Attachment::Failed) ?: Attachment.Refused(flavours)
    }

    private suspend fun detach() {
        val attached = observer ?: return
        observer = null
        try {
            val configuration = core.remote.call(subject, "get_configuration") { node.component.ref.get_configuration() }
            core.remote.call(subject, "remove_service_profile") { configuration.remove_service_profile(attached.profileId) }
        } catch (e: RtcException) {
            log.debug("{}: could not detach observer: {}", subject, e.message)
        } finally {
            attached.close()
        }
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

        fun now(): Long = System.nanoTime() / 1_000_000
    }
}
