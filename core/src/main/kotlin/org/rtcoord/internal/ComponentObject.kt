package org.rtcoord.internal

import RTC.ExecutionContext
import RTC.PortService
import RTC.RTObject
import _SDOPackage.Configuration
import java.lang.ref.WeakReference
import java.util.concurrent.atomic.AtomicLong
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.withContext
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.ComponentSummary
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerNode
import org.rtcoord.RtcPath
import org.rtcoord.summary

/**
 * A live component: its reference and the latest snapshot read from it. Reads are serialised per component (one refresh
 * at a time; a caller takes the result of a read that started after it arrived, never of one that may have missed what
 * it wrote); different components refresh in parallel; readers take [snapshot]'s value without waiting.
 */
internal class ComponentObject(private val core: TreeCore, val ref: RTObject) {
    /** One read at a time, in the order they were asked for. */
    private val reads = TurnLock()
    private val current = MutableStateFlow<ComponentSnapshot?>(null)
    private val currentSummary = MutableStateFlow<ComponentSummary?>(null)

    /** Execution contexts by the component's handle for them, as of the last refresh. */
    @Volatile
    var contexts: Map<Int, ExecutionContext> = emptyMap()
        private set

    /**
     * Port references by short port name, as the last read found them, held weakly: a burst of port operations after a
     * read takes them from here, while an idle tree keeps none (each reference costs JacORB about a kilobyte, several
     * times what the rest of a port's snapshot does).
     */
    @Volatile private var ports = WeakReference<Map<String, PortService>>(null)

    /** The reference of the port named [name] (without the instance prefix), null if the component has none such. */
    suspend fun port(subject: String, name: String): PortService? =
        ports.get()?.get(name)
            ?: withContext(core.remote.callDispatcher()) { ComponentReader(core.remote, subject, ref).readPorts() }
                .also { ports = WeakReference(it) }[name]

    /** Replaced whole, under a lock, when a listing finds a new node: a component has one host or none, found again. */
    @Volatile private var hosts: Map<RtcPath, ManagerNode> = emptyMap()

    /** The managers whose listings showed this component, the latest node of each. */
    val hostingManagers: Collection<ManagerNode>
        get() = hosts.values

    /** Records that [manager]'s listing shows this component. */
    fun hostedBy(manager: ManagerNode) {
        if (hosts[manager.path] === manager) return
        synchronized(this) { hosts = hosts + (manager.path to manager) }
    }

    /**
     * The nodes at which the tree shows this component, one per path, in the order they were found: replaced whole
     * under the lock, as nearly every component is shown at one path.
     */
    @Volatile private var nodes: List<ComponentNode> = emptyList()

    /** The paths at which the tree shows this component, in the order they were found. */
    val knownPaths: List<RtcPath>
        get() = nodes.map { it.path }

    /**
     * The one node that stands for the component in every event, log line and result: the first found in a naming
     * context (where it registered itself), else the first found at all (below a manager, whose listing is an alias).
     * The latest node at that path, since a listing may make it anew.
     */
    val canonical: ComponentNode?
        get() = preferred(nodes)

    /**
     * The node of [found] (some of this component's nodes, as one walk found them) that stands for it: the [canonical]
     * one when it is among them, else by the same rule among them alone.
     */
    fun canonicalAmong(found: Collection<ComponentNode>): ComponentNode {
        val paths = found.mapTo(HashSet()) { it.path }
        return preferred(nodes.filter { it.path in paths }) ?: found.first()
    }

    private fun preferred(nodes: Collection<ComponentNode>): ComponentNode? =
        nodes.firstOrNull { !it.path.isAlias } ?: nodes.firstOrNull()

    /** Records that the tree shows this component at [node]'s path. */
    fun knownAs(node: ComponentNode) {
        synchronized(this) {
            val index = nodes.indexOfFirst { it.path == node.path }
            nodes =
                when {
                    nodes.isEmpty() -> listOf(node)
                    index < 0 -> nodes + node
                    else -> nodes.toMutableList().also { it[index] = node }
                }
        }
    }

    val snapshot: StateFlow<ComponentSnapshot?>
        get() = current

    /** The summary of the latest read, full or not. */
    val summary: StateFlow<ComponentSummary?>
        get() = currentSummary

    /** The snapshot, read now if none was read yet. */
    suspend fun loaded(subject: String): ComponentSnapshot = current.value ?: refresh(subject)

    /**
     * The instance name: the snapshot's, else the one the summary read in the caller's survey gave (or its failure),
     * else read from the profile alone.
     */
    suspend fun instanceName(subject: String): String =
        current.value?.instanceName
            ?: SurveyReads.current()?.instanceName(this)
            ?: core.remote.call(subject, "get_component_profile") { ref.get_component_profile() }.instance_name

    /** The component's configuration object, once known. */
    @Volatile private var configuration: Configuration? = null

    /**
     * Orders the reads: each read of the whole component ([refresh]) or of its states ([stamp]) takes the next stamp as
     * it starts, so a read can tell whether another started after it, or after a write.
     */
    private val stamps = AtomicLong()

    /** The stamp of the latest whole read published. */
    @Volatile private var lastRead = 0L

    /**
     * By context handle, the stamp of the read behind the state published: a state read that started earlier never
     * replaces it. Guarded by [publishing], which makes each publication one step.
     */
    private val stateStamps = HandleMap<Long>()
    private val publishing = Any()

    /** The stamp of a read of states starting now; pass it to [publishStates] with what it found. */
    fun stamp(): Long = stamps.incrementAndGet()

    /** Reads the component again (its configuration too, once that was read) and publishes the result. */
    suspend fun refresh(subject: String): ComponentSnapshot {
        val arrived = stamps.get()
        return reads.withTurn {
            // Only a read that started after this caller arrived is as fresh as its own would be: one that
            // started before may have missed what the caller just wrote.
            current.value.takeIf { lastRead > arrived }
                ?: withContext(core.remote.callDispatcher()) {
                    val stamp = stamp()
                    val reader = ComponentReader(core.remote, subject, ref)
                    val withConfiguration = current.value?.configuration != null
                    val settings = async { if (withConfiguration) readConfiguration(reader) else null }
                    val reading = reader.read()
                    contexts = reading.contexts
                    ports = WeakReference(reading.ports)
                    publishRead(reading.snapshot.copy(configuration = settings.await()), stamp).also {
                        lastRead = stamp
                    }
                }
        }
    }

    /** Publishes [read], a whole read stamped [stamp], keeping each context's state that a later read found. */
    private fun publishRead(read: ComponentSnapshot, stamp: Long): ComponentSnapshot =
        synchronized(publishing) {
            val previous = current.value?.contexts.orEmpty().associateBy { it.handle }
            val contexts =
                read.contexts.map { context ->
                    val later = previous[context.handle]?.takeIf { (stateStamps[context.handle] ?: 0) > stamp }
                    if (later == null) stateStamps[context.handle] = stamp
                    later?.let { context.copy(state = it.state) } ?: context
                }
            show(read.copy(contexts = contexts))
        }

    /**
     * Publishes [states] by context handle, read by the read stamped [stamp], onto the latest snapshot (whatever else
     * was published since stays); a context whose state a later read found keeps it.
     */
    fun publishStates(states: Map<Int, LifeCycle>, stamp: Long) {
        synchronized(publishing) {
            val latest = current.value ?: return
            val updated = latest.withStates { context ->
                states[context.handle]
                    ?.takeIf { stamp > (stateStamps[context.handle] ?: 0) }
                    ?.also { stateStamps[context.handle] = stamp }
            }
            // A read that found every state as shown, as nearly every read does, changes nothing to show.
            if (updated !== latest) show(updated)
        }
    }

    private fun show(snapshot: ComponentSnapshot): ComponentSnapshot {
        current.value = snapshot
        currentSummary.value = snapshot.summary
        return snapshot
    }

    /**
     * Reads what a listing shows (see [ComponentSummary]) and publishes it; the snapshot stays as it was. In a survey,
     * the first path that reaches the component reads it, the others take that read.
     */
    suspend fun refreshSummary(subject: String): ComponentSummary {
        val survey = SurveyReads.current() ?: return readSummary(subject).summary
        return survey.summary(this) { readSummary(subject) }.summary
    }

    private suspend fun readSummary(subject: String): ComponentReader.SummaryReading = reads.withTurn {
        withContext(core.remote.callDispatcher()) { ComponentReader(core.remote, subject, ref).readSummary() }
            .also { currentSummary.value = it.summary }
    }

    /**
     * Reads the configuration sets and publishes them with the rest of the latest snapshot. Read while no other read
     * runs, so that a read started earlier, which may have missed a write, cannot publish after it.
     */
    suspend fun loadConfiguration(subject: String): ConfigurationSnapshot {
        loaded(subject)
        return reads.withTurn {
            readConfiguration(ComponentReader(core.remote, subject, ref)).also { settings ->
                synchronized(publishing) { current.value = current.value!!.copy(configuration = settings) }
            }
        }
    }

    private suspend fun readConfiguration(reader: ComponentReader): ConfigurationSnapshot {
        val (settings, target) = reader.readConfiguration(configuration)
        configuration = target
        return settings
    }
}
