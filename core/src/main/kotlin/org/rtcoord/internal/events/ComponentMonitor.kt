package org.rtcoord.internal.events

import java.util.concurrent.CompletableFuture
import java.util.concurrent.Future
import java.util.concurrent.TimeUnit
import java.util.concurrent.TimeoutException
import kotlin.time.Duration
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.async
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentNode
import org.rtcoord.LifeCycle
import org.rtcoord.PortTraffic
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.WatchMethod
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.toLifeCycle
import org.slf4j.LoggerFactory

/**
 * Watches one component for every registration interested in it: the shell around its [ComponentWatch], which decides
 * everything. One coroutine takes what happened (hints, ticks, timers, markers, watchdog checks, registrations changed)
 * in batches, in order, asks the machine what to do, and carries out each step it returns (a CORBA read, attaching or
 * detaching the observer), the events to publish and the timers to set; so the component's events come out in the order
 * they happened, and delivery to handlers is the sinks' job. Its observer is [ObserverLink]'s, its tick and watchdog
 * [MonitorTimers]'.
 */
internal class ComponentMonitor(
    private val core: TreeCore,
    private val host: ObserverHost,
    val node: ComponentNode,
    private val ended: (ComponentMonitor) -> Unit,
) {
    /** What the coroutine takes: an input for the machine, with what must be told once it is served. */
    private class Work(
        val input: WatchInput,
        val done: (() -> Unit)? = null,
        val ready: CompletableDeferred<Unit>? = null,
    )

    private val log = LoggerFactory.getLogger(ComponentMonitor::class.java)
    private val subject = node.path.toString()
    private val registrations = MonitorRegistrations()
    /** Work not yet taken; guarded by the monitor, and made anew at each batch taken, so an idle one holds no array. */
    private var inbox = ArrayDeque<Work>()
    /** Whether a coroutine takes the [inbox]'s work; guarded by the monitor. */
    private var working = false
    /** Whether the monitor was stopped: it takes no more work, and its coroutine ends once the inbox is empty. */
    private var stopping = false

    /**
     * How the component is watched, as its machine last decided and the reports were told; set through
     * [WatchReports.announce].
     */
    @Volatile var method: WatchMethod? = null

    // Owned by the worker coroutine.
    private val watch = ComponentWatch(node, now())
    /** The timer of each kind on its way, by the kind's ordinal: an array weighs half an empty map. */
    private val armed = arrayOfNulls<Future<*>>(ComponentWatch.Timer.entries.size)
    private val link = ObserverLink(core, host, subject, node.component)
    private val stopped = CompletableFuture<Unit>()
    /** Work that arrived during a read and was not taken with it: the next batch's. */
    private var carried = ArrayList<Work>(0)
    private val fsm = ObservedFsmState(node)
    private val probe: StateProbe? =
        core.requests
            .takeIf { it.supports(node.component.ref) }
            ?.let { requests ->
                StateProbe(requests, node.component.ref, node.component::stamp, { timers.heard() }) { outcome ->
                    val input =
                        if (outcome is StateProbe.Outcome.Changed)
                            WatchInput.Probed(outcome.states, outcome.epoch, outcome.stamp)
                        else WatchInput.Unsettled
                    if (!send(Work(input, outcome.done))) outcome.done()
                }
            }
    private val timers =
        MonitorTimers(
            core,
            probe,
            core.clock,
            { done -> if (!send(Work(WatchInput.Ticked, done))) done() },
        ) { heardAt ->
            send(Work(WatchInput.Overdue(heardAt)))
        }

    /** Adds [registration] and returns once the component was read and, if asked for, observed. */
    suspend fun add(registration: MonitorRegistration) {
        registrations += registration
        val ready = CompletableDeferred<Unit>()
        if (send(Work(WatchInput.Reconfigured, ready = ready))) ready.await()
    }

    /** Removes [registration]; returns whether none is left (the caller then [stop]s the monitor). */
    fun remove(registration: MonitorRegistration): Boolean {
        registrations -= registration
        send(Work(WatchInput.Reconfigured))
        return registrations.isEmpty()
    }

    /** The tree's heartbeat floor changed: the watching is arranged anew, its observer attached at the new floor. */
    fun rearrange() {
        send(Work(WatchInput.Reconfigured))
    }

    /** Something this component depends on failed (its manager): a read tells at once whether it answers. */
    fun suspect() {
        send(Work(WatchInput.ReadWanted))
    }

    /** Stops watching: polling ends and the observer is detached, soon, by the monitor's coroutine. */
    fun stop() {
        val start =
            synchronized(this) {
                stopping = true
                !working.also { working = true }
            }
        if (start) startWorking()
    }

    /** Hands [work] to the monitor's coroutine, starting one if none runs; false once the monitor was stopped. */
    private fun send(work: Work): Boolean {
        val start =
            synchronized(this) {
                if (stopping) return false
                inbox.addLast(work)
                !working.also { working = true }
            }
        if (start) startWorking()
        return true
    }

    /**
     * Starts the coroutine that takes the monitor's work, which ends when none is left: a tree watching ten thousand
     * components would otherwise hold as many coroutines waiting, which weigh more than the rest of a monitor.
     */
    private fun startWorking() {
        // On the dispatcher of remote calls, which its reads then make without changing threads.
        core.scope.launch(core.remote.dispatcher) { run() }
    }

    /**
     * Waits, at most [timeout], until the monitor's coroutine has finished (its observer detached), on the calling
     * thread: the tree is closing. Call [stop] first.
     */
    fun awaitStopped(timeout: Duration) {
        val done = runCatching { stopped.get(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS) }
        if (done.exceptionOrNull() is TimeoutException)
            log.warn("{}: observer not detached within {}", subject, timeout)
    }

    /** Where the registrations' events go. */
    fun sinks(): List<EventSink> = registrations.map { it.sink }

    private suspend fun run() {
        var idle = false
        try {
            while (true) {
                val batch = nextBatch()
                if (batch == null) {
                    idle = true
                    return
                }
                if (batch.isEmpty()) return
                handle(batch)
            }
        } finally {
            if (!idle) end()
        }
    }

    /**
     * The work to take next: null when there is none and the monitor runs on (its coroutine then ends), empty once
     * stopped.
     */
    private fun nextBatch(): List<Work>? {
        val batch = carried.also { carried = ArrayList(0) }
        synchronized(this) {
            batch += inbox
            inbox = ArrayDeque()
            if (batch.isEmpty() && !stopping) {
                working = false
                return null
            }
        }
        return batch
    }

    /** Ends the monitor, stopped or failed: its timers and observer go. */
    private suspend fun end() {
        withContext(NonCancellable) {
            armed.forEach { it?.cancel(false) }
            timers.stop()
            probe?.close()
            link.detach()
            ended(this@ComponentMonitor)
            stopped.complete(Unit)
        }
    }

    private suspend fun handle(batch: List<Work>) {
        // A timer that fired is done with: its future, and the work it holds, need not wait for the next one.
        for (work in batch) {
            val fired = work.input as? WatchInput.Fired ?: continue
            if (armed[fired.timer.ordinal]?.isDone == true) armed[fired.timer.ordinal] = null
        }
        watch.needs = registrations.needs(core.watcher.heartbeats.floor)
        val disagreed = !watch.agreed
        val decision = watch.decide(batch.map { it.input }, now())
        publish(decision.events)
        try {
            perform(decision.step)
            if (disagreed && watch.agreed) core.disagreementsEnded.incrementAndGet()
        } finally {
            // Before the ticks are done: the probe of the next one expects what this batch found.
            probe?.expect(
                watch.last
                    ?.takeIf { watch.settled }
                    ?.let { StateProbe.Expectation.of(it, node.component.contexts, watch.epoch) }
            )
            batch.forEach {
                it.ready?.complete(Unit)
                it.done?.invoke()
            }
        }
    }

    /** Carries out [step], and what the machine makes of it. */
    private suspend fun perform(step: WatchStep) {
        when (step) {
            WatchStep.Idle -> Unit
            WatchStep.ReadAll -> readAndPublish()
            is WatchStep.ReadStates -> readStates(step.handles)
            is WatchStep.TakeStates -> takeStates(step.states, step.stamp)
            WatchStep.Settle -> carryOut(watch.settle(now(), lateHints()))
            is WatchStep.Attach -> attach(step)
            WatchStep.Detach -> {
                link.detach()
                carryOut(watch.detached())
            }
            WatchStep.Drop -> link.drop()
        }
    }

    /** Attaches an observer as [step] says, passing what it hears to [received]. */
    private suspend fun attach(step: WatchStep.Attach) {
        fsm.forget()
        val attachment = link.attach(step.advertised, step.heartbeat, step.traffic, ::received)
        // Its heartbeats are awaited from now.
        if (attachment is Attachment.Attached) timers.heard()
        carryOut(watch.attached(attachment, now()))
    }

    /** Reads only the states of the contexts [handles] and hands them to the machine. */
    private suspend fun readStates(handles: Set<Int>) {
        val contexts = node.component.contexts
        if (handles.any { it !in contexts }) return readAndPublish()
        suspend fun state(handle: Int) =
            core.remote
                .call(subject, "get_component_state") {
                    contexts.getValue(handle).get_component_state(node.component.ref)
                }
                .toLifeCycle()
        val stamp = node.component.stamp()
        val states =
            try {
                // One context, the common case, is read without a coroutine per read.
                handles.singleOrNull()?.let { mapOf(it to state(it)) }
                    ?: coroutineScope { handles.associateWith { async { state(it) } }.mapValues { it.value.await() } }
            } catch (e: RtcException) {
                return carryOut(watch.failed(e, now()))
            }
        takeStates(states, stamp)
    }

    /**
     * Hands [states], read by the read stamped [stamp], to the component (for reads after writes) and to the machine.
     */
    private suspend fun takeStates(states: Map<Int, LifeCycle>, stamp: Long) {
        node.component.publishStates(states, stamp)
        carryOut(watch.statesRead(states, now(), lateHints(), node.component.snapshot.value))
    }

    private suspend fun readAndPublish() {
        val snapshot =
            try {
                node.component.refresh(subject)
                if (registrations.configuration && node.component.snapshot.value?.configuration == null) {
                    node.component.loadConfiguration(subject)
                }
                node.component.snapshot.value!!
            } catch (e: RtcException) {
                return carryOut(watch.failed(e, now()))
            }
        carryOut(watch.read(snapshot, now(), lateHints()))
    }

    /**
     * The hints that arrived while the component was being read, for the machine to take before it reconciles: they
     * tell of changes made before it answered. Everything else waits for the next batch.
     */
    private fun lateHints(): List<WatchInput.Hinted> {
        val hints = ArrayList<WatchInput.Hinted>()
        while (true) {
            val item = synchronized(this) { inbox.removeFirstOrNull() } ?: return hints
            val hinted = item.input as? WatchInput.Hinted
            if (hinted != null && hinted.hint.kind == HintKind.RTC_STATUS) hints += hinted else carried += item
        }
    }

    private suspend fun carryOut(outcome: WatchOutcome) {
        carried += outcome.untaken.map { Work(it) }
        if (outcome.readAgain) carried += Work(WatchInput.ReadWanted)
        outcome.marker?.let(link::sendMarker)
        // Each fires when the clock reads its time, not a millisecond later as a delay may; one armed anew replaces its
        // kind's.
        for ((timer, at) in outcome.timers) {
            val future = core.at(at) { send(Work(WatchInput.Fired(timer, at))) } ?: continue
            armed[timer.ordinal]?.cancel(false)
            armed[timer.ordinal] = future
        }
        for (change in outcome.changes) {
            when (change) {
                ComponentLiveness.Change.Finalized -> log.info("{}: finalized", subject)
                ComponentLiveness.Change.Unreachable ->
                    log.info(
                        "{}: {}; probing until it answers again",
                        subject,
                        outcome.events.filterIsInstance<BecameZombie>().firstOrNull()?.cause?.reason,
                    )
                ComponentLiveness.Change.Recovered -> log.info("{}: answers again", subject)
                is ComponentLiveness.Change.Lost -> Unit
            }
        }
        val arranged = outcome.arranged
        arranged.schedule?.let {
            timers.poll(it.pollPeriod)
            timers.watch(it.heartbeat)
        }
        arranged.askManagersEvery?.let { core.watcher.outages.componentSilent(node, it) }
        publish(outcome.events)
        arranged.method?.let { method ->
            if (method != this.method) log.debug("{}: watched by {}", subject, method)
            core.watcher.reports.announce(this, method, registrations.toList())
        }
        perform(arranged.next)
    }

    /**
     * What the observer received, on the ORB's thread. A heartbeat only says when (see [MonitorTimers]); data flowing
     * and FSM states entered change nothing a read would show, and go straight to the registrations ([PortTraffic] to
     * those that asked for it).
     */
    private fun received(hint: Hint) {
        val traffic = hint.traffic()
        when {
            hint.kind == HintKind.OTHER && hint.text.startsWith(ComponentWatch.MARKER_PREFIX) ->
                send(Work(WatchInput.MarkerBack(hint.text)))
            hint.isHeartbeat -> timers.heard()
            traffic != null ->
                timers.heard().also {
                    core.model.publish(
                        listOf(PortTraffic(node, traffic.first, traffic.second)),
                        deliver = registrations::offerTraffic,
                    )
                }
            hint.kind == HintKind.FSM_STATUS ->
                timers.heard().also {
                    fsm.changedBy(hint)?.let { core.model.publish(listOf(it), deliver = registrations::offer) }
                }
            else -> send(Work(WatchInput.Hinted(hint, now())))
        }
    }

    /** Publishes [events] through the tree's model, with the states they leave the component in. */
    private fun publish(events: List<RtcEvent>) {
        core.model.publish(events, node.component, watch.published, registrations::offer)
    }

    private fun now(): Long = core.clock.now()
}
