package org.rtcoord.internal

import java.util.concurrent.ExecutorService
import java.util.concurrent.Future
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.ScheduledThreadPoolExecutor
import java.util.concurrent.SynchronousQueue
import java.util.concurrent.ThreadFactory
import java.util.concurrent.ThreadPoolExecutor
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.asCoroutineDispatcher
import org.rtcoord.ClosedException

/**
 * The threads of one tree, which end when it closes: kotlinx's shared dispatchers keep their workers for the life of
 * the JVM, and in an OSGi framework those workers hold the bundle's class loader after the bundle stopped.
 *
 * [dispatcher] runs the tree's coroutines and their timers on up to [concurrency] threads, as many as remote calls in
 * flight: work that makes calls may block in JacORB (connecting, sending) besides the calls themselves. [submit] runs
 * each blocking remote call on a thread of its own, so that a caller who gives up is not held by a call JacORB will not
 * interrupt (it ignores interrupts until its own timeout); [calls] runs the calls of callers who wait for them, and the
 * work that makes many, on the same threads.
 */
internal class TreeThreads(concurrency: Int) : AutoCloseable {
    private val scheduled =
        ScheduledThreadPoolExecutor(concurrency, factory("rtcoord-tree")).apply {
            removeOnCancelPolicy = true
            executeExistingDelayedTasksAfterShutdownPolicy = false
            setKeepAliveTime(IDLE_SECONDS, TimeUnit.SECONDS)
            allowCoreThreadTimeOut(true)
        }
    private val callThreads: ExecutorService =
        ThreadPoolExecutor(
            0,
            Int.MAX_VALUE,
            IDLE_SECONDS,
            TimeUnit.SECONDS,
            SynchronousQueue(),
            factory("rtcoord-call"),
        )

    /** Where the tree's coroutines run. */
    val dispatcher: CoroutineDispatcher = scheduled.asCoroutineDispatcher()

    /** The threads that block in remote calls, as many as needed: [Remote] limits how many run at once. */
    val calls: CoroutineDispatcher = callThreads.asCoroutineDispatcher()

    /**
     * Runs [task] on a thread of the tree once [delayNanos] have passed, to the nanosecond rather than the millisecond
     * a coroutine's `delay` rounds up to; null once the tree is closed.
     */
    fun schedule(delayNanos: Long, task: Runnable): Future<*>? =
        try {
            scheduled.schedule(task, delayNanos, TimeUnit.NANOSECONDS)
        } catch (e: RejectedExecutionException) {
            null
        }

    /** Runs the blocking [call] on a thread of its own; fails with [ClosedException] once the tree is closed. */
    fun submit(call: Runnable): Future<*> =
        try {
            callThreads.submit(call)
        } catch (e: RejectedExecutionException) {
            throw ClosedException("tree")
        }

    /**
     * Ends the threads once the tasks they have are done: idle ones at once, a call still blocked when its ORB lets go
     * of it. Called when the tree's coroutines have all ended: a coroutine still finishing would find its dispatcher
     * gone, and kotlinx would resume it on its own shared threads instead.
     */
    override fun close() {
        scheduled.shutdown()
        callThreads.shutdown()
    }

    private companion object {
        /** How long an idle thread is kept before it ends. */
        const val IDLE_SECONDS = 10L

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
