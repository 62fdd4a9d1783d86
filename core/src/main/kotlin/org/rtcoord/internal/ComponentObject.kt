package org.rtcoord.internal

import RTC.ExecutionContext
import RTC.PortService
import RTC.RTObject
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.ComponentSnapshot
import org.rtcoord.RtcPath
import java.util.concurrent.CopyOnWriteArraySet

/**
 * A live component: its reference and the latest snapshot read from it. Reads are serialised per
 * component (one refresh at a time, a caller arriving during one gets its result); different
 * components refresh in parallel; readers take [snapshot]'s value without waiting.
 */
internal class ComponentObject(private val core: TreeCore, val ref: RTObject) {
    private val refreshing = Mutex()
    private val current = MutableStateFlow<ComponentSnapshot?>(null)

    private val paths = CopyOnWriteArraySet<RtcPath>()

    /** Execution contexts by the component's handle for them, as of the last refresh. */
    @Volatile var contexts: Map<Int, ExecutionContext> = emptyMap()
        private set

    /** Port references by short port name, as of the last refresh. */
    @Volatile var ports: Map<String, PortService> = emptyMap()
        private set

    /** The paths at which the tree shows this component, in the order they were found. */
    val knownPaths: List<RtcPath> get() = paths.toList()

    fun knownAt(path: RtcPath) {
        paths += path
    }

    val snapshot: StateFlow<ComponentSnapshot?> get() = current

    /** The snapshot, read now if none was read yet. */
    suspend fun loaded(subject: String): ComponentSnapshot = current.value ?: refresh(subject)

    /** Reads the component again and publishes the result. */
    suspend fun refresh(subject: String): ComponentSnapshot {
        val before = current.value
        return refreshing.withLock {
            // Someone refreshed while this caller waited: that read is as fresh as ours would be.
            current.value.takeIf { it !== before && it != null } ?: ComponentReader(core.remote, subject, ref).read().let { reading ->
                contexts = reading.contexts
                ports = reading.ports
                current.value = reading.snapshot
                reading.snapshot
            }
        }
    }

    /** Publishes [snapshot] as the latest, after an operation whose effect is known. */
    fun publish(snapshot: ComponentSnapshot) {
        current.value = snapshot
    }
}
