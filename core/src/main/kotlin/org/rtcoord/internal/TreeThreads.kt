package org.rtcoord.internal

import java.util.concurrent.Future
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.ScheduledThreadPoolExecutor
import java.util.concurrent.SynchronousQueue
import java.util.concurrent.ThreadFactory
import java.util.concurrent.ThreadPoolExecutor
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.asCoroutineDispatcher
import org.rtcoord.ClosedException

/**
 * The threads of one tree, which end when it closes: kotlinx's shared dispatchers keep their workers for the life of
 * the JVM, and in an OSGi framework those workers hold the bundle's class loader after the bundle stopped.
 *
 * One pool of threads does the tree's work, made when no idle one is free and ended after [idle] without work; the idle
 * thread most recently busy takes the next task, so a quiet tree keeps only the few its heartbeats and timers need (a
 * coordinator runs for months beside the components it watches: a pool of fixed size kept 32 threads of a 67-thread
 * `rtcoord watch` alive under 1 s heartbeats). One more thread keeps the time of delays and timers, in the robot's time
 * at [speed] (see [org.rtcoord.TreeConfig.speed]).
 *
 * [dispatcher] runs the tree's coroutines, at most [concurrency] at once: work that makes calls may block in JacORB
 * (connecting, sending) besides the calls themselves. [submit] runs each blocking remote call on a thread of its own,
 * so that a caller who gives up is not held by a call JacORB will not interrupt (it ignores interrupts until its own
 * timeout); [calls] runs the calls of callers who wait for them, and the work that makes many, on the same pool.
 */
internal class TreeThreads(concurrency: Int, speed: Double = 1.0, idle: Duration = IDLE) : AutoCloseable {
    private val workers =
        ThreadPoolExecutor(
            0,
            Int.MAX_VALUE,
            idle.inWholeMilliseconds,
            TimeUnit.MILLISECONDS,
            SynchronousQueue(),
            factory("rtcoord-tree"),
        )
    private val timer =
        ScheduledThreadPoolExecutor(1, factory("rtcoord-timer")).apply {
            removeOnCancelPolicy = true
            executeExistingDelayedTasksAfterShutdownPolicy = false
            setKeepAliveTime(idle.inWholeMilliseconds, TimeUnit.MILLISECONDS)
            allowCoreThreadTimeOut(true)
        }
    private val timed = TimedExecutor(workers, timer, speed)

    /** The threads that block in remote calls, as many as needed: [Remote] limits how many run at once. */
    val calls: CoroutineDispatcher = timed.asCoroutineDispatcher()

    /** Where the tree's coroutines run. */
    val dispatcher: CoroutineDispatcher = calls.limitedParallelism(concurrency)

    /**
     * Runs [task] on a thread of the tree once [delayNanos] have passed, to the nanosecond rather than the millisecond
     * a coroutine's `delay` rounds up to; null once the tree is closed.
     */
    fun schedule(delayNanos: Long, task: Runnable): Future<*>? =
        try {
            if (delayNanos <= 0) workers.submit(task) else timed.schedule(task, delayNanos, TimeUnit.NANOSECONDS)
        } catch (e: RejectedExecutionException) {
            null
        }

    /** Runs the blocking [call] on a thread of its own; fails with [ClosedException] once the tree is closed. */
    fun submit(call: Runnable): Future<*> =
        try {
            workers.submit(call)
        } catch (e: RejectedExecutionException) {
            throw ClosedException("tree")
        }

    /**
     * Ends the threads once the tasks they have are done: idle ones at once, a call still blocked when its ORB lets go
     * of it. Called when the tree's coroutines have all ended: a coroutine still finishing would find its dispatcher
     * gone, and kotlinx would resume it on its own shared threads instead.
     */
    override fun close() {
        timed.shutdown()
    }

    private companion object {
        /** How long an idle thread is kept before it ends. */
        val IDLE = 10.seconds

        /**
         * Daemon threads (a tree left open does not keep the JVM up) whose context class loader is the library's, not
         * whichever the first caller had: JacORB loads through it, and a thread must not hold on to a caller's loader
         * (another plug-in's) for its whole life.
         */
        fun factory(prefix: String): ThreadFactory {
            val count = AtomicInteger()
            val loader = TreeThreads::class.java.classLoader
            return ThreadFactory { task ->
                Thread(task, "$prefix-${count.incrementAndGet()}").apply {
                    isDaemon = true
                    contextClassLoader = loader
                }
            }
        }
    }
}
