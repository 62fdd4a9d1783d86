package org.rtcoord.internal

import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import org.rtcoord.TreeConfig
import org.rtcoord.internal.events.Watcher
import org.slf4j.LoggerFactory
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicLong

/** What every node of one tree shares: the ORB, the remote-call runner, the scope and the registry. */
internal class TreeCore(val config: TreeConfig) : AutoCloseable {
    private val log = LoggerFactory.getLogger("org.rtcoord.RtcTree")

    val orb = OrbHolder(config.orb, config.listenAddress, config.callTimeout)
    val remote = Remote(config.concurrency, config.callTimeout)
    val scope = CoroutineScope(
        SupervisorJob() + CoroutineName("rtc-tree") + CoroutineExceptionHandler { _, e -> log.warn("tree task failed: {}", e.toString()) },
    )
    val components = ComponentRegistry(this)
    val watcher = Watcher(this)

    /** Poll ticks that found the previous one still waiting and were folded into it (see [RtcTree.missedPollTicks]). */
    val missedPollTicks = AtomicLong()
    private val closed = AtomicBoolean()

    override fun close() {
        if (!closed.compareAndSet(false, true)) return
        watcher.close()
        scope.cancel()
        orb.close()
    }
}
