package org.rtcoord.internal

import java.util.concurrent.Future
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineExceptionHandler
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.job
import org.rtcoord.NameServerNode
import org.rtcoord.TreeConfig
import org.rtcoord.internal.data.DataTaps
import org.rtcoord.internal.events.ListenerFailures
import org.rtcoord.internal.events.MillisClock
import org.rtcoord.internal.events.Watcher
import org.rtcoord.internal.logs.LogRecords
import org.rtcoord.internal.model.SystemModel
import org.slf4j.LoggerFactory

/**
 * What every node of one tree shares: the ORB, the remote-call runner, the scope, the registry and the model.
 * [nameServers] are the tree's name servers; the host of the first is asked when the ORB starts.
 */
internal class TreeCore(val config: TreeConfig, val nameServers: () -> List<NameServerNode>) : AutoCloseable {
    private val log = LoggerFactory.getLogger("org.rtcoord.RtcTree")

    val orb =
        OrbHolder(
            config.orb as org.omg.CORBA.ORB?,
            {
                config.listenAddress
                    ?: listenAddressToward(nameServers().firstOrNull()?.address?.substringBeforeLast(':'))
            },
            config.callTimeout / config.speed,
        )
    private val threads = TreeThreads(config.concurrency, config.speed)
    val remote = Remote(config.concurrency, config.callTimeout, orbEnforcesDeadline = orb.owned, threads)

    /** Where the tree's periodic listings run, all of them together: the listings of a system come at once. */
    val background = BackgroundCalls(remote.dispatcher.limitedParallelism(BackgroundCalls.PARALLELISM))
    val scope =
        CoroutineScope(
            SupervisorJob() +
                threads.dispatcher +
                CoroutineName("rtc-tree") +
                CoroutineExceptionHandler { _, e ->
                    log.warn("tree task failed: {}", e.toString())
                    log.debug("tree task failed", e)
                } +
                ListenerFailures(config.listenerFailures)
        )
    /** The tree's clock: the robot's time, [TreeConfig.speed] times as fast as the host's when that is not 1. */
    val time: TimeSource.WithComparableMarks =
        if (config.speed == 1.0) TimeSource.Monotonic else ScaledTimeSource(config.speed)

    /** The monotonic clock of every component monitor. */
    val clock = MillisClock(time)

    /** Runs [task] on the tree's threads when [clock] reads [millis]; null once the tree is closed. */
    fun at(millis: Long, task: Runnable): Future<*>? = threads.schedule(clock.nanosUntil(millis), task)

    /** Runs [task] on the tree's threads as soon as one is free; not once the tree is closed. */
    fun execute(task: Runnable) {
        threads.schedule(0, task)
    }

    val components = ComponentRegistry(this)
    val model = SystemModel(nameServers)
    val watcher = Watcher(this)
    val taps = DataTaps(this)
    val logs = LogRecords(this)

    /** Requests whose replies no thread waits for; made on first use, when the ORB has started. */
    val requests by lazy { AsyncRequests(orb::rootPoa, scope) }

    /** Poll ticks that found the previous one still waiting and were folded into it (see [RtcTree.missedPollTicks]). */
    val missedPollTicks = AtomicLong()

    /**
     * Disagreements between a component's hints and its reads that ended, the reads finding where the hints lead or one
     * deciding once the grace period passed; counted as the batch that ended one is done. A test that sent hints no
     * read confirms waits on it to know they were settled, where it would wait out the grace period.
     */
    val disagreementsEnded = AtomicLong()
    private val closed = AtomicBoolean()

    init {
        // The threads end once the last of the tree's coroutines has (see TreeThreads.close).
        scope.coroutineContext.job.invokeOnCompletion { threads.close() }
    }

    private fun listenAddressToward(nameServer: String?): String =
        ListenAddress.toward(nameServer).also {
            log.debug("listening on {}, the address that reaches {}", it, nameServer ?: "this host")
        }

    override fun close() {
        if (!closed.compareAndSet(false, true)) return
        watcher.close()
        taps.close()
        logs.close()
        scope.cancel()
        orb.close()
    }
}
