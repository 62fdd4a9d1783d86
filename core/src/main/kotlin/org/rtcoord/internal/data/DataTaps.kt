package org.rtcoord.internal.data

import java.util.concurrent.atomic.AtomicBoolean
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.rtcoord.DataListener
import org.rtcoord.Port
import org.rtcoord.RtcException
import org.rtcoord.Subscription
import org.rtcoord.internal.ComponentObject
import org.rtcoord.internal.TreeCore
import org.slf4j.LoggerFactory

/**
 * The tree's data taps: one per out-port, shared by every listener of that port, connected with the first and removed
 * with the last, and every one removed when the tree closes.
 */
internal class DataTaps(private val core: TreeCore) {
    private val log = LoggerFactory.getLogger(DataTaps::class.java)
    private val host by lazy { TapHost(core.orb.orb, core.orb::rootPoa) }
    private val changes = Mutex()
    private val taps = HashMap<Pair<ComponentObject, String>, DataTap>()
    private val closed = AtomicBoolean()

    /** Adds [listener] to [port]'s tap, connecting the tap first if it is the first; returns once connected. */
    suspend fun subscribe(port: Port, listener: DataListener): Subscription {
        val key = port.component.component to port.name
        changes.withLock {
            check(!closed.get()) { "the tree is closed" }
            val tap =
                synchronized(taps) { taps[key] }
                    ?: DataTap(core, port, host).also {
                        it.connect()
                        synchronized(taps) { taps[key] = it }
                    }
            tap.add(listener)
        }
        val cancelled = AtomicBoolean()
        return Subscription {
            if (cancelled.compareAndSet(false, true)) core.scope.launch { release(key, listener) }
        }
    }

    private suspend fun release(key: Pair<ComponentObject, String>, listener: DataListener) {
        changes.withLock {
            val tap = synchronized(taps) { taps[key] } ?: return
            if (!tap.remove(listener)) return
            synchronized(taps) { taps.remove(key) }
            try {
                tap.disconnect()
            } catch (e: RtcException) {
                log.info("could not remove a data tap: {}", e.message)
            }
        }
    }

    /** Removes every tap, on the calling thread, each within the ORB's call deadline. */
    fun close() {
        closed.set(true)
        val all = synchronized(taps) { taps.values.toList().also { taps.clear() } }
        all.forEach(DataTap::disconnectNow)
    }
}
