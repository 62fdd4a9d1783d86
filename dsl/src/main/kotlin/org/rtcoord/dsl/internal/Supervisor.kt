package org.rtcoord.dsl.internal

import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.Overlap
import org.rtcoord.ParameterChanged
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.dsl.Escalation
import org.rtcoord.dsl.RestartType
import org.rtcoord.dsl.Strategy
import org.rtcoord.dsl.Supervision
import org.rtcoord.dsl.SupervisorActivity

/**
 * Runs one [Supervision]: watches its components and recovers them as the strategy says, within the restart intensity
 * its [RestartPolicy] keeps; what recovery needs is kept by a [SupervisionRecord], and a component that is gone is
 * brought back by a [ChildRestorer]. Failures are handled one episode at a time, in the order they arrive, by one
 * coroutine of [scope]; the record is kept under a lock the recovery holds, so a recovery never sees it half updated.
 *
 * @param activity what it has done, for those who show it: made with the coordinator, so that it can be followed before
 *   the supervisor starts.
 * @param escalate runs the script's escalation handlers.
 */
internal class Supervisor(
    private val supervision: Supervision,
    val activity: SupervisorActivity,
    private val engine: Engine,
    private val scope: CoroutineScope,
    log: (String) -> Unit,
    /** What the restart intensity is counted on: tests turn it by hand, with the back-off's delays. */
    time: TimeSource = TimeSource.Monotonic,
    private val escalate: suspend (Escalation) -> Unit,
) {
    /** A failure to handle: [child] did [what] while it was [node]. [exited]: it ended by itself. */
    private class Failure(
        val child: SupervisedChild,
        val node: ComponentNode,
        val what: String,
        val exited: Boolean,
        val seq: Long,
    )

    private val name = supervision.name
    private val say = RecoveryLog(name, log)
    private val children =
        supervision.children.mapIndexed { index, ref -> SupervisedChild(index, ref, supervision.restartOf(ref)) }
    private val record = SupervisionRecord(engine.tree, children, say)
    private val restorer = ChildRestorer(engine, record, say)
    private val lock = Mutex()
    private val failures = Channel<Failure>(Channel.UNLIMITED)
    /** Numbers failures as they are reported, so a restart can tell which reports it already answered. */
    private val sequence = AtomicLong()
    /** Per child: the last failure number its latest restart answers (only the handling coroutine touches it). */
    private val covered = HashMap<SupervisedChild, Long>()
    private val policy =
        time.markNow().let { start ->
            RestartPolicy(supervision.maxRestarts, supervision.backoff) { start.elapsedNow() }
        }
    @Volatile private var stopped = false
    /** Failures reported and not answered yet: restarted, left, or found to be no news. */
    private val unanswered = AtomicInteger()
    @Volatile private var handling: Job? = null

    /**
     * Whether every failure reported so far is answered, or the supervisor has stopped: nothing it was told of is still
     * to come.
     */
    internal val quiet: Boolean
        get() = handling?.isActive != true || unanswered.get() == 0

    /** Resolves and watches the components, records what recovery needs, and starts handling failures. */
    suspend fun start() {
        lock.withLock {
            children.forEach { it.name = engine.identities.followed(it.ref.selector) }
            children
                .groupBy { child -> children.first { it.node.isSameComponent(child.node) } }
                .values
                .firstOrNull { it.size > 1 }
                ?.let { same ->
                    throw IllegalArgumentException("$name: ${same.joinToString { it.ref.selector }} are one component")
                }
            children.forEach { watch(it) }
            record.takeAll()
        }
        activity.children(children.map { it.toString() })
        say.line("supervising ${children.joinToString()} (${supervision.strategy})")
        handling = scope.launch {
            for (failure in failures) {
                if (stopped) break
                // Failures reported together (one process killed) are one episode.
                val reported = listOf(failure) + generateSequence { failures.tryReceive().getOrNull() }
                try {
                    catchFailure({ handle(reported) }) { e ->
                        say.line(
                            "recovering ${reported.joinToString { it.node.path.toString() }} failed: ${e.message ?: e}"
                        )
                    }
                } finally {
                    unanswered.addAndGet(-reported.size)
                }
            }
        }
    }

    /** Stops watching; a recovery under way is cancelled with the coordinator's scope. Idempotent. */
    fun close() {
        stopped = true
        failures.close()
        children.forEach { it.subscription?.cancel() }
    }

    /**
     * Watches [child]'s component, and the one that replaces it once re-created. A failure must never be dropped:
     * whatever the script watches with, the supervisor queues its events.
     */
    private suspend fun watch(child: SupervisedChild) {
        val events =
            HandlerQueue(scope, Overlap.QUEUE) { event: RtcEvent ->
                (event.source as? ComponentNode)?.let { observe(child, it, event) }
            }
        child.subscription =
            engine.identities.listen(child.ref.selector, setOf(RtcEvent::class.java), listener = events::offer)
    }

    private suspend fun observe(child: SupervisedChild, node: ComponentNode, event: RtcEvent) {
        when (event) {
            is StateChanged -> if (event.new == LifeCycle.ERROR) report(child, node, "entered ERROR", exited = false)
            is HeartbeatLost -> report(child, node, "was lost (silent for ${event.silentMillis} ms)", exited = false)
            is BecameZombie -> report(child, node, "became unreachable (${event.cause.reason})", exited = false)
            is ComponentFinalized -> report(child, node, "exited", exited = true)
            is PortConnected,
            is PortDisconnected,
            is ConfigurationSetActivated,
            is ParameterChanged ->
                lock.withLock {
                    if (!child.left && child.node.isSameComponent(node)) record.update(child, event)
                }
            else -> Unit
        }
    }

    private fun report(child: SupervisedChild, node: ComponentNode, what: String, exited: Boolean) {
        unanswered.incrementAndGet()
        if (failures.trySend(Failure(child, node, what, exited, sequence.incrementAndGet())).isFailure)
            unanswered.decrementAndGet()
    }

    /**
     * One restart episode: every child that failed by now (those reported, and siblings lost in the same fault, such as
     * the components of one killed process) is recovered by one decision, which counts once against the restart
     * intensity.
     */
    private suspend fun handle(reported: List<Failure>) {
        val fresh = reported.filter { it.isNews() }
        if (fresh.isEmpty()) return
        val episode = sequence.get()
        val failed = LinkedHashMap<SupervisedChild, String>()
        for (child in children.filter { !it.left }) {
            val report = fresh.firstOrNull { it.child === child }
            val status = child.status()
            when {
                report?.exited == true -> failed[child] = report.what
                status is ChildStatus.Gone -> failed[child] = report?.what ?: "is gone (${status.reason})"
                (status as ChildStatus.Up).state == LifeCycle.ERROR -> failed[child] = report?.what ?: "is in ERROR"
                report != null ->
                    say.line("$child ${report.what}, but it answers and is ${status.state}: nothing to recover")
            }
        }
        failed.keys.forEach { covered[it] = episode }
        failed.forEach { (child, what) -> say.line("$child $what") }
        val exited = fresh.filter { it.exited }.map { it.child }.toSet()
        for (child in failed.keys.toList()) {
            when {
                child.restart == RestartType.TEMPORARY -> leave(child, "it is temporary: not restarted")
                child.restart == RestartType.TRANSIENT && child in exited ->
                    leave(child, "it is transient and exited by itself: not restarted")
                else -> continue
            }
            failed -= child
        }
        if (failed.isEmpty()) return
        when (val decision = policy.decide(failed.keys.map { it.index }.toSet())) {
            is RestartPolicy.Decision.Escalate ->
                failed.entries.first().let { (child, what) -> giveUp(child, what, decision.restarts) }
            is RestartPolicy.Decision.Restart -> {
                val together = failed.keys.joinToString()
                if (decision.wait.isPositive()) {
                    activity.waiting(decision.wait)
                    say.line("restarting $together in ${decision.wait} (consecutive restart ${decision.attempt})")
                    val waited = failed.keys.associateWith { it.node }
                    delay(decision.wait)
                    failed.keys
                        .filter { child -> replacedMeanwhile(child, waited.getValue(child)) }
                        .forEach { failed -= it }
                    if (failed.isEmpty()) return
                }
                // Whatever was reported of them meanwhile, this restart answers.
                sequence.get().let { now -> failed.keys.forEach { covered[it] = now } }
                if (failed.size > 1) say.line("$together failed together: one restart")
                lock.withLock { restart(failed.keys.toList()) }
                activity.restarted(together, children.map { it.toString() })
            }
        }
    }

    /**
     * Whether someone else re-created [child] in place of [failed] while the restart waited, and the new component
     * runs: it is followed, not restarted (a new one in ERROR is still restarted).
     */
    private suspend fun replacedMeanwhile(child: SupervisedChild, failed: ComponentNode): Boolean = lock.withLock {
        restorer.replacement(child, failed) ?: return false
        (child.status() as? ChildStatus.Up)?.state.let { it != null && it != LifeCycle.ERROR }
    }

    /** Whether this failure is news: about the component the child is now, and after its last restart began. */
    private fun Failure.isNews(): Boolean =
        !child.left && child.node.isSameComponent(node) && seq > (covered[child] ?: 0L)

    /**
     * Restarts [failed] and, as the strategy says, the others: those not failed are stopped in reverse order, then all
     * are started in declared order. Where the others depend on the earlier ones (rest-for-one, one-for-all), starting
     * stops at the first that does not come up: the later ones stay stopped until it does. One that did not come up is
     * retried as a failure of its own. Each it starts again is counted as it is ([SupervisorActivity.startingAgain]).
     */
    private suspend fun restart(failed: List<SupervisedChild>) {
        val group =
            when (supervision.strategy) {
                Strategy.ONE_FOR_ONE -> failed
                Strategy.ONE_FOR_ALL -> children
                Strategy.REST_FOR_ONE -> children.drop(failed.minOf { it.index })
            }.filter { !it.left }
        if (group.size > failed.size) {
            say.line("${supervision.strategy}: restarting ${group.joinToString()}")
            group.asReversed().filter { it !in failed }.forEach { stop(it) }
        }
        val inOrder = supervision.strategy != Strategy.ONE_FOR_ONE
        var notStarted: SupervisedChild? = null
        for ((place, member) in group.withIndex()) {
            if (member !in failed && member.restart == RestartType.TEMPORARY) {
                leave(member, "it is temporary: stopped, not started again")
                continue
            }
            activity.startingAgain(member.toString())
            if (start(member)) continue
            notStarted = notStarted ?: member
            if (inOrder) {
                group
                    .drop(place + 1)
                    .filter { !it.left }
                    .takeIf { it.isNotEmpty() }
                    ?.let { later ->
                        say.line("${later.joinToString()} stay stopped until $member starts")
                    }
                break
            }
        }
        // The next try counts against the intensity like any restart.
        notStarted?.let { report(it, it.node, "could not be restarted", exited = false) }
    }

    private suspend fun stop(member: SupervisedChild) {
        when (val status = member.status()) {
            is ChildStatus.Up ->
                say.attempt("stop $member") { if (status.state == LifeCycle.ACTIVE) member.node.deactivate() }
            is ChildStatus.Gone -> say.line("stop $member: it is gone (${status.reason})")
        }
    }

    /**
     * Brings [member] up (reset; followed when someone else re-created it; re-created when gone) and activates it;
     * returns whether it is ACTIVE.
     */
    private suspend fun start(member: SupervisedChild): Boolean {
        say.line("start $member")
        var status = member.status()
        if (status is ChildStatus.Gone && restorer.replacement(member, member.node) != null) status = member.status()
        when (status) {
            is ChildStatus.Gone -> {
                restorer.recreate(member, status.reason) ?: return false
                restorer.restore(member)
            }
            is ChildStatus.Up ->
                if (status.state == LifeCycle.ERROR)
                    say.attempt("reset $member") { member.node.reset() } ?: return false
        }
        return say.attempt("activate $member") {
            if (member.node.state() != LifeCycle.ACTIVE) member.node.activate()
        } != null
    }

    private fun leave(child: SupervisedChild, why: String) {
        child.left = true
        child.subscription?.cancel()
        say.line("$child: $why; no longer supervised")
    }

    private suspend fun giveUp(child: SupervisedChild, what: String, restarts: Int) {
        val escalation = Escalation(name, child.node.path.toString(), what, restarts, supervision.maxRestarts.period)
        activity.escalated(escalation.reason)
        say.line("escalation: ${escalation.reason}; the supervisor stops")
        close()
        escalate(escalation)
    }
}
