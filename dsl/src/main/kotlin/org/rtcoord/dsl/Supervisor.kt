package org.rtcoord.dsl

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.BadParameterException
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ConfigurationSetActivated
import org.rtcoord.Connection
import org.rtcoord.EventOptions
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerNode
import org.rtcoord.NodeFilters
import org.rtcoord.NodeKind
import org.rtcoord.OperationFailedException
import org.rtcoord.Overlap
import org.rtcoord.ParameterChanged
import org.rtcoord.Port
import org.rtcoord.PortConnected
import org.rtcoord.PortDisconnected
import org.rtcoord.RtcEvent
import org.rtcoord.RtcException
import org.rtcoord.RtcPath
import org.rtcoord.RtcTree
import org.rtcoord.StateChanged
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.TimeSource

/**
 * Runs one [Supervision]: watches its components, keeps a record of their connections and active
 * configuration sets, and recovers them as the strategy says. Failures are handled one at a time, in
 * the order they arrive, by one coroutine of [scope]; the records are kept under a lock the recovery
 * holds, so a recovery never sees them half updated.
 *
 * @param escalate runs the script's escalation handlers.
 */
internal class Supervisor(
    private val supervision: Supervision,
    private val tree: RtcTree,
    private val engine: Engine,
    watching: EventOptions,
    private val scope: CoroutineScope,
    private val log: (String) -> Unit,
    private val escalate: suspend (Escalation) -> Unit,
) {
    /** A failure to handle: [child] did [what] while it was [node]. [exited]: it ended by itself. */
    private class Failure(val child: SupervisedChild, val node: ComponentNode, val what: String, val exited: Boolean, val seq: Long)

    /** What a component answers when asked for its state. */
    private sealed class Status {
        class Up(val state: LifeCycle) : Status()
        class Gone(val reason: String) : Status()
    }

    private val name = supervision.name
    // A failure must never be dropped: whatever the script watches with, the supervisor queues its events.
    private val options = EventOptions(watching.mode, watching.pollPeriod, Overlap.QUEUE, watching.heartbeat, watching.missedBeats)
    private val children = supervision.children.mapIndexed { index, ref -> SupervisedChild(index, ref, supervision.restartOf(ref)) }
    private val connections = mutableListOf<RecordedConnection>()
    private val lock = Mutex()
    private val failures = Channel<Failure>(Channel.UNLIMITED)
    /** Numbers failures as they are reported, so a restart can tell which reports it already answered. */
    private val sequence = AtomicLong()
    /** Per child: the last failure number its latest restart answers (only the handling coroutine touches it). */
    private val covered = HashMap<SupervisedChild, Long>()
    private val policy = TimeSource.Monotonic.markNow().let { start -> RestartPolicy(supervision.maxRestarts, supervision.backoff) { start.elapsedNow() } }
    @Volatile private var stopped = false

    /** What it has done, for those who show it. */
    val activity = SupervisorActivity(name, supervision.strategy.name)

    /** Resolves and watches the components, records what recovery needs, and starts handling failures. */
    suspend fun start() {
        lock.withLock {
            children.forEach { it.node = engine.component(it.ref.selector) }
            children.groupBy { child -> children.first { it.node.isSameComponent(child.node) } }.values.firstOrNull { it.size > 1 }?.let { same ->
                throw IllegalArgumentException("$name: ${same.joinToString { it.ref.selector }} are one component")
            }
            children.forEach { watch(it) }
            val managers = tree.find(predicate = NodeFilters.kind(NodeKind.MANAGER)).toList().filterIsInstance<ManagerNode>()
            children.forEach { record(it, managers) }
            children.forEach { child -> child.node.snapshot().ports.filter { it.connectors.isNotEmpty() }.forEach { recordConnections(child, it.name) } }
        }
        activity.children(children.map { it.toString() })
        log("$name: supervising ${children.joinToString()} (${supervision.strategy})")
        scope.launch {
            for (failure in failures) {
                if (stopped) break
                // Failures reported together (one process killed) are one episode.
                val reported = listOf(failure) + generateSequence { failures.tryReceive().getOrNull() }
                try {
                    handle(reported)
                } catch (e: CancellationException) {
                    throw e
                } catch (e: Exception) {
                    log("$name: recovering ${reported.joinToString { it.node.path.toString() }} failed: ${e.message ?: e}")
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

    private suspend fun watch(child: SupervisedChild) {
        val node = child.node
        child.subscription = tree.on(node, RtcEvent::class.java, options) { event -> observe(child, node, event) }
    }

    private suspend fun observe(child: SupervisedChild, node: ComponentNode, event: RtcEvent) {
        when (event) {
            is StateChanged -> if (event.new == LifeCycle.ERROR) report(child, node, "entered ERROR", exited = false)
            is HeartbeatLost -> report(child, node, "was lost (silent for ${event.silentMillis} ms)", exited = false)
            is BecameZombie -> report(child, node, "became unreachable (${event.cause.reason})", exited = false)
            is ComponentFinalized -> report(child, node, "exited", exited = true)
            is PortConnected, is PortDisconnected, is ConfigurationSetActivated, is ParameterChanged -> lock.withLock {
                if (!child.left && child.node.isSameComponent(node)) update(child, event)
            }
            else -> Unit
        }
    }

    private fun report(child: SupervisedChild, node: ComponentNode, what: String, exited: Boolean) {
        failures.trySend(Failure(child, node, what, exited, sequence.incrementAndGet()))
    }

    /** Records [child]'s type, name, hosting managers (among [managers]) and active configuration set. */
    private suspend fun record(child: SupervisedChild, managers: List<ManagerNode>) {
        val node = child.node
        val snapshot = node.snapshot()
        child.typeName = snapshot.typeName
        child.instanceName = snapshot.instanceName
        val configuration = node.configuration()
        child.configuration = configuration.activeSet?.let { id -> configuration.sets[id]?.let { RecordedConfiguration(id, it) } }
        val host = managers.firstOrNull { manager ->
            val hosted = try { manager.children() } catch (e: RtcException) { emptyList() }
            hosted.any { it is ComponentNode && it.isSameComponent(node) }
        }
        child.managers = host?.let { managersAbove(it.path.child(node.name)) }.orEmpty()
        if (host == null) log("$name: no manager hosts ${node.path}: it can be reset, not re-created")
    }

    /** The managers above [path] (a component below a manager, a slave below its master), nearest first. */
    private suspend fun managersAbove(path: RtcPath): List<ManagerNode> =
        generateSequence(path.parent) { it.parent }.takeWhile { it.names.isNotEmpty() }.toList()
            .mapNotNull { above -> try { tree.node(above) as? ManagerNode } catch (e: RtcException) { null } }

    /** Records the connections of [child]'s port [port] that are not recorded yet ([only] that one, when given). */
    private suspend fun recordConnections(child: SupervisedChild, port: String, only: String? = null) {
        for (connection in child.node.port(port).connections()) {
            if ((only != null && connection.id != only) || connections.any { it.id == connection.id }) continue
            val ends = connection.ports.map { end -> endOf(end) }
            if (ends.any { it == null }) {
                log("$name: connection ${connection.name} has a port the tree does not know (${connection.ports.joinToString { it.fullName }}): it will not be made again")
                continue
            }
            val recorded = RecordedConnection(connection.id, connection.name, connection.properties, ends.filterNotNull())
            connections += recorded
            log("$name: recorded connection $recorded")
        }
    }

    private suspend fun endOf(end: Connection.End): RecordedConnection.End? {
        val path = end.path ?: return null
        val port = path.port ?: return null
        val component = path.withPort(null)
        val owner = children.firstOrNull { it.node.path == component }
            ?: try { tree.component(component.toString()) } catch (e: RtcException) { null }?.let { node -> children.firstOrNull { it.node.isSameComponent(node) } }
        return owner?.let { RecordedConnection.End.Supervised(it, port) } ?: RecordedConnection.End.External(path)
    }

    /** Keeps [child]'s records up to date with [event]. */
    private suspend fun update(child: SupervisedChild, event: RtcEvent) {
        when (event) {
            is PortConnected -> if (connections.none { it.id == event.connector.id }) recordConnections(child, event.port, only = event.connector.id)
            is PortDisconnected -> {
                val connection = connections.firstOrNull { it.id == event.connector.id } ?: return
                // A connection lost because one of its components failed or exits (it leaves its execution
                // contexts first, so it reads as CREATED) is made again with it; one removed while all its
                // components run normally was removed on purpose.
                if (connection.children.all { (probe(it) as? Status.Up)?.state in RUNNING }) {
                    connections -= connection
                    log("$name: connection $connection was removed: it will not be made again")
                }
            }
            is ConfigurationSetActivated -> {
                // None active is a passing state (a set was written and is about to be activated): keep the record.
                val set = event.new ?: return
                val values = child.node.snapshot().configuration?.sets?.get(set) ?: return
                child.configuration = RecordedConfiguration(set, values)
                log("$name: ${child.node.path} runs configuration set $set")
            }
            is ParameterChanged -> {
                val recorded = child.configuration?.takeIf { it.set == event.set } ?: return
                child.configuration = recorded.copy(values = event.new?.let { recorded.values + (event.name to it) } ?: (recorded.values - event.name))
            }
            else -> Unit
        }
    }

    /**
     * One restart episode: every child that failed by now (those reported, and siblings lost in the same
     * fault, such as the components of one killed process) is recovered by one decision, which counts
     * once against the restart intensity.
     */
    private suspend fun handle(reported: List<Failure>) {
        val fresh = reported.filter { it.isNews() }
        if (fresh.isEmpty()) return
        val episode = sequence.get()
        val failed = LinkedHashMap<SupervisedChild, String>()
        for (child in children.filter { !it.left }) {
            val report = fresh.firstOrNull { it.child === child }
            val status = probe(child)
            when {
                report?.exited == true -> failed[child] = report.what
                status is Status.Gone -> failed[child] = report?.what ?: "is gone (${status.reason})"
                (status as Status.Up).state == LifeCycle.ERROR -> failed[child] = report?.what ?: "is in ERROR"
                report != null -> log("$name: $child ${report.what}, but it answers and is ${status.state}: nothing to recover")
            }
        }
        failed.keys.forEach { covered[it] = episode }
        failed.forEach { (child, what) -> log("$name: $child $what") }
        val exited = fresh.filter { it.exited }.map { it.child }.toSet()
        for (child in failed.keys.toList()) {
            when {
                child.restart == RestartType.TEMPORARY -> leave(child, "it is temporary: not restarted")
                child.restart == RestartType.TRANSIENT && child in exited -> leave(child, "it is transient and exited by itself: not restarted")
                else -> continue
            }
            failed -= child
        }
        if (failed.isEmpty()) return
        when (val decision = policy.decide(failed.keys.map { it.index }.toSet())) {
            is RestartPolicy.Decision.Escalate -> failed.entries.first().let { (child, what) -> giveUp(child, what, decision.restarts) }
            is RestartPolicy.Decision.Restart -> {
                val together = failed.keys.joinToString()
                if (decision.wait.isPositive()) {
                    activity.waiting(decision.wait)
                    log("$name: restarting $together in ${decision.wait} (consecutive restart ${decision.attempt})")
                    delay(decision.wait)
                }
                // Whatever was reported of them meanwhile, this restart answers.
                sequence.get().let { now -> failed.keys.forEach { covered[it] = now } }
                if (failed.size > 1) log("$name: $together failed together: one restart")
                lock.withLock { restart(failed.keys.toList()) }
                activity.restarted(together, children.map { it.toString() })
            }
        }
    }

    /** Whether this failure is news: about the component the child is now, and after its last restart began. */
    private fun Failure.isNews(): Boolean = !child.left && child.node.isSameComponent(node) && seq > (covered[child] ?: 0L)

    /**
     * Restarts [failed] and, as the strategy says, the others: those not failed are stopped in reverse
     * order, then all are started in declared order. Where the others depend on the earlier ones
     * (rest-for-one, one-for-all), starting stops at the first that does not come up: the later ones
     * stay stopped until it does. One that did not come up is retried as a failure of its own.
     */
    private suspend fun restart(failed: List<SupervisedChild>) {
        val group = when (supervision.strategy) {
            Strategy.ONE_FOR_ONE -> failed
            Strategy.ONE_FOR_ALL -> children
            Strategy.REST_FOR_ONE -> children.drop(failed.minOf { it.index })
        }.filter { !it.left }
        if (group.size > failed.size) {
            log("$name: ${supervision.strategy}: restarting ${group.joinToString()}")
            group.asReversed().filter { it !in failed }.forEach { stop(it) }
        }
        val inOrder = supervision.strategy != Strategy.ONE_FOR_ONE
        var notStarted: SupervisedChild? = null
        for ((place, member) in group.withIndex()) {
            if (member !in failed && member.restart == RestartType.TEMPORARY) {
                leave(member, "it is temporary: stopped, not started again")
                continue
            }
            if (start(member)) continue
            notStarted = notStarted ?: member
            if (inOrder) {
                group.drop(place + 1).filter { !it.left }.takeIf { it.isNotEmpty() }?.let { later ->
                    log("$name: ${later.joinToString()} stay stopped until $member starts")
                }
                break
            }
        }
        // The next try counts against the intensity like any restart.
        notStarted?.let { report(it, it.node, "could not be restarted", exited = false) }
    }

    private suspend fun stop(member: SupervisedChild) {
        when (val status = probe(member)) {
            is Status.Up -> attempt("stop $member") { if (status.state == LifeCycle.ACTIVE) member.node.deactivate() }
            is Status.Gone -> log("$name: stop $member: it is gone (${status.reason})")
        }
    }

    /** Brings [member] up (reset, or re-created when gone) and activates it; returns whether it is ACTIVE. */
    private suspend fun start(member: SupervisedChild): Boolean {
        log("$name: start $member")
        when (val status = probe(member)) {
            is Status.Gone -> recreate(member, status.reason) ?: return false
            is Status.Up -> if (status.state == LifeCycle.ERROR) attempt("reset $member") { member.node.reset() } ?: return false
        }
        return attempt("activate $member") { if (member.node.state() != LifeCycle.ACTIVE) member.node.activate() } != null
    }

    /**
     * Re-creates [child] through its managers, watches the new component in place of the old one, and
     * restores its configuration and connections; returns the new node, or null if no manager made it.
     */
    private suspend fun recreate(child: SupervisedChild, reason: String): ComponentNode? {
        val old = child.node
        log("$name: ${old.path} is gone ($reason)")
        if (child.managers.isEmpty()) {
            log("$name: re-create ${old.path} failed: no manager hosted it when it was first seen")
            return null
        }
        val created = child.managers.firstNotNullOfOrNull { createThrough(it, child) } ?: return null
        val node = placed(old, created)
        // The old component's observer and probing end here; the new one is watched in its place.
        child.subscription?.cancel()
        child.node = node
        child.instanceName = node.snapshot().instanceName
        child.managers = (managersAbove(created.path) + child.managers).distinctBy { it.path }
        log("$name: re-created ${old.path} as ${node.path}")
        engine.follow(old, node)
        watch(child)
        restoreConfiguration(child)
        restoreConnections(child)
        return node
    }

    /** Creates [child] anew through [manager]: with its old name, or one the manager chooses if it refuses that. */
    private suspend fun createThrough(manager: ManagerNode, child: SupervisedChild): ComponentNode? {
        val what = "re-create ${child.instanceName} (${child.typeName}) through ${manager.path}"
        log("$name: $what")
        return try {
            manager.create(child.typeName, child.instanceName)
        } catch (e: OperationFailedException) {
            // No component came back: the name may still be held by the old, unresponsive instance.
            log("$name: $what failed: ${e.message}; trying a name the manager chooses")
            attempt("re-create ${child.typeName} through ${manager.path}") { manager.create(child.typeName) }
        } catch (e: RtcException) {
            log("$name: $what failed: ${e.message}")
            null
        }
    }

    /** [created] as the naming context of [old] shows it (the path users know), else as its manager does. */
    private suspend fun placed(old: ComponentNode, created: ComponentNode): ComponentNode {
        val context = old.path.parent ?: return created
        return try {
            tree.refresh(context, depth = 0)
            (tree.node(context.child(created.name)) as? ComponentNode)?.takeIf { it.isSameComponent(created) } ?: created
        } catch (e: RtcException) {
            created
        }
    }

    private suspend fun restoreConfiguration(child: SupervisedChild) {
        val recorded = child.configuration ?: return
        val node = child.node
        attempt("restore configuration set ${recorded.set} of ${node.path}") {
            val current = node.configuration()
            val values = current.sets[recorded.set]
            if (values == null) {
                node.addConfigurationSet(recorded.set, recorded.values)
            } else {
                recorded.values.filter { (parameter, value) -> values[parameter] != value }.forEach { (parameter, value) ->
                    log("$name: set ${node.path} parameter $parameter=$value in ${recorded.set}")
                    node.setParameter(parameter, value, recorded.set)
                }
            }
            if (current.activeSet != recorded.set) node.activateConfigurationSet(recorded.set)
        }
    }

    /** Makes [child]'s recorded connections again, each once all its supervised components are back. */
    private suspend fun restoreConnections(child: SupervisedChild) {
        for (connection in connections.filter { it.involves(child) }) {
            val away = connection.children.filter { it !== child }.firstOrNull { probe(it) is Status.Gone }
            if (away != null) {
                log("$name: reconnect $connection: waits until $away is back")
                continue
            }
            attempt("reconnect $connection") {
                val ports = connection.ends.map { portOf(it) }
                // Live ports still hold the connector to the dead component: it would stay beside the new one.
                connection.ends.zip(ports).filter { (end, _) -> !(end is RecordedConnection.End.Supervised && end.child === child) }
                    .forEach { (_, port) -> removeStale(port, connection.id) }
                connection.id = ports.first().connect(ports.drop(1), connection.properties, connection.name).id
            }
        }
    }

    private suspend fun portOf(end: RecordedConnection.End): Port = when (end) {
        is RecordedConnection.End.Supervised -> end.child.node.port(end.port)
        is RecordedConnection.End.External -> tree.port(end.path.toString())
    }

    private suspend fun removeStale(port: Port, id: String) {
        if (port.connections().none { it.id == id }) return
        attempt("remove stale connector $id from ${port.path}") {
            try {
                port.disconnect(id)
            } catch (e: BadParameterException) {
                // Gone meanwhile: what this step wanted.
            }
        }
    }

    private suspend fun probe(child: SupervisedChild): Status = try {
        Status.Up(child.node.state())
    } catch (e: RtcException) {
        Status.Gone(e.reason)
    }

    private fun leave(child: SupervisedChild, why: String) {
        child.left = true
        child.subscription?.cancel()
        log("$name: $child: $why; no longer supervised")
    }

    private suspend fun giveUp(child: SupervisedChild, what: String, restarts: Int) {
        val escalation = Escalation(name, child.node.path.toString(), what, restarts, supervision.maxRestarts.period)
        activity.escalated(escalation.reason)
        log("$name: escalation: ${escalation.reason}; the supervisor stops")
        close()
        escalate(escalation)
    }

    /** Runs one recovery step, logged as [what]; a failure is logged with the step and gives null. */
    private suspend fun <T> attempt(what: String, action: suspend () -> T): T? {
        log("$name: $what")
        return try {
            action()
        } catch (e: CancellationException) {
            throw e
        } catch (e: Exception) {
            log("$name: $what failed: ${e.message ?: e}")
            null
        }
    }

    private companion object {
        /** The states of a component that works normally, active or not. */
        val RUNNING = setOf(LifeCycle.ACTIVE, LifeCycle.INACTIVE)
    }
}
