package org.rtcoord.internal

import RTC.ExecutionContext
import RTC.PortService
import RTC.RTObject
import _SDOPackage.Configuration
import kotlinx.coroutines.async
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import kotlinx.coroutines.withContext
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.ComponentSummary
import org.rtcoord.ConfigurationSnapshot
import org.rtcoord.ManagerNode
import org.rtcoord.RtcPath
import org.rtcoord.summary

/**
 * A live component: its reference and the latest snapshot read from it. Reads are serialised per
 * component (one refresh at a time, a caller arriving during one gets its result); different
 * components refresh in parallel; readers take [snapshot]'s value without waiting.
 */
internal class ComponentObject(private val core: TreeCore, val ref: RTObject) {
    private val refreshing = Mutex()
    private val current = MutableStateFlow<ComponentSnapshot?>(null)
    private val currentSummary = MutableStateFlow<ComponentSummary?>(null)

    /** Execution contexts by the component's handle for them, as of the last refresh. */
    @Volatile var contexts: Map<Int, ExecutionContext> = emptyMap()
        private set

    /** Port references by short port name, as of the last refresh. */
    @Volatile var ports: Map<String, PortService> = emptyMap()
        private set

    private val hosts = java.util.concurrent.ConcurrentHashMap<RtcPath, ManagerNode>()

    /** The managers whose listings showed this component, the latest node of each. */
    val hostingManagers: Collection<ManagerNode> get() = hosts.values

    /** Records that [manager]'s listing shows this component. */
    fun hostedBy(manager: ManagerNode) {
        hosts[manager.path] = manager
    }

    /** The nodes at which the tree shows this component, by path, in the order they were found. */
    private val nodes = LinkedHashMap<RtcPath, ComponentNode>()

    /** The paths at which the tree shows this component, in the order they were found. */
    val knownPaths: List<RtcPath> get() = synchronized(nodes) { nodes.keys.toList() }

    /**
     * The one node that stands for the component in every event, log line and result: the first found in
     * a naming context (where it registered itself), else the first found at all (below a manager, whose
     * listing is an alias). The latest node at that path, since a listing may make it anew.
     */
    val canonical: ComponentNode?
        get() = synchronized(nodes) { nodes.values.firstOrNull { !it.path.isAlias } ?: nodes.values.firstOrNull() }

    /** Records that the tree shows this component at [node]'s path. */
    fun knownAs(node: ComponentNode) {
        synchronized(nodes) { nodes[node.path] = node }
    }

    val snapshot: StateFlow<ComponentSnapshot?> get() = current

    /** The summary of the latest read, full or not. */
    val summary: StateFlow<ComponentSummary?> get() = currentSummary

    /** The snapshot, read now if none was read yet. */
    suspend fun loaded(subject: String): ComponentSnapshot = current.value ?: refresh(subject)

    /**
     * The instance name: the snapshot's, else the one the summary read in the caller's survey gave (or its
     * failure), else read from the profile alone.
     */
    suspend fun instanceName(subject: String): String =
        current.value?.instanceName ?: SurveyReads.current()?.instanceName(this)
            ?: core.remote.call(subject, "get_component_profile") { ref.get_component_profile() }.instance_name

    /** The component's configuration object, once known. */
    @Volatile private var configuration: Configuration? = null

    /** How many reads completed; an operation's [publish] does not count, it knows only what it changed. */
    @Volatile private var reads = 0L

    /** Reads the component again (its configuration too, once that was read) and publishes the result. */
    suspend fun refresh(subject: String): ComponentSnapshot {
        val readsBefore = reads
        return refreshing.withLock {
            // A read that finished while this caller waited is as fresh as its own would be.
            current.value.takeIf { reads != readsBefore } ?: withContext(core.remote.dispatcher) {
                val reader = ComponentReader(core.remote, subject, ref)
                val withConfiguration = current.value?.configuration != null
                val settings = async { if (withConfiguration) readConfiguration(reader) else null }
                val reading = reader.read()
                contexts = reading.contexts
                ports = reading.ports
                reading.snapshot.copy(configuration = settings.await()).also {
                    current.value = it
                    currentSummary.value = it.summary
                    reads++
                }
            }
        }
    }

    /**
     * Reads what a listing shows (see [ComponentSummary]) and publishes it; the snapshot stays as it was.
     * In a survey, the first path that reaches the component reads it, the others take that read.
     */
    suspend fun refreshSummary(subject: String): ComponentSummary {
        val survey = SurveyReads.current() ?: return readSummary(subject).summary
        return survey.summary(this) { readSummary(subject) }.summary
    }

    private suspend fun readSummary(subject: String): ComponentReader.SummaryReading = refreshing.withLock {
        withContext(core.remote.dispatcher) { ComponentReader(core.remote, subject, ref).readSummary() }.also { currentSummary.value = it.summary }
    }

    /** Reads the configuration sets and publishes them with the rest of the latest snapshot. */
    suspend fun loadConfiguration(subject: String): ConfigurationSnapshot {
        val snapshot = loaded(subject)
        val settings = readConfiguration(ComponentReader(core.remote, subject, ref))
        refreshing.withLock { current.value = (current.value ?: snapshot).copy(configuration = settings) }
        return settings
    }

    private suspend fun readConfiguration(reader: ComponentReader): ConfigurationSnapshot {
        val (settings, target) = reader.readConfiguration(configuration)
        configuration = target
        return settings
    }

    /** Publishes [snapshot] as the latest, after an operation whose effect is known. */
    fun publish(snapshot: ComponentSnapshot) {
        current.value = snapshot
        currentSummary.value = snapshot.summary
    }
}
