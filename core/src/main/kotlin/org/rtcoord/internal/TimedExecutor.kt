package org.rtcoord.internal

import java.util.concurrent.AbstractExecutorService
import java.util.concurrent.Callable
import java.util.concurrent.Delayed
import java.util.concurrent.ExecutorService
import java.util.concurrent.Future
import java.util.concurrent.FutureTask
import java.util.concurrent.RejectedExecutionException
import java.util.concurrent.ScheduledExecutorService
import java.util.concurrent.ScheduledFuture
import java.util.concurrent.TimeUnit

/**
 * Runs tasks on [workers] and keeps their times on [timer]: a task due later waits on the timer's one thread, then runs
 * on a worker. So the threads that run work can be as few as the work needs at the moment, while kotlinx, which
 * schedules a coroutine's `delay` on an executor's own timer when the executor is a [ScheduledExecutorService], keeps
 * every delay of the tree's coroutines on the tree's threads.
 *
 * A task due once the workers are shut down is dropped, as a delayed task is at shutdown. Delays are in the robot's
 * time, which runs [speed] times as fast as the host's (see [org.rtcoord.TreeConfig.speed]).
 */
internal class TimedExecutor(
    private val workers: ExecutorService,
    private val timer: ScheduledExecutorService,
    private val speed: Double = 1.0,
) : AbstractExecutorService(), ScheduledExecutorService {
    override fun execute(command: Runnable) = workers.execute(command)

    override fun schedule(command: Runnable, delay: Long, unit: TimeUnit): ScheduledFuture<*> =
        timer.schedule(handOver(command), hostNanos(delay, unit), TimeUnit.NANOSECONDS)

    override fun <V> schedule(callable: Callable<V>, delay: Long, unit: TimeUnit): ScheduledFuture<V> {
        val task = FutureTask(callable)
        return HandedOver(timer.schedule(handOver(task), hostNanos(delay, unit), TimeUnit.NANOSECONDS), task)
    }

    override fun scheduleAtFixedRate(
        command: Runnable,
        initialDelay: Long,
        period: Long,
        unit: TimeUnit,
    ): ScheduledFuture<*> =
        timer.scheduleAtFixedRate(
            handOver(command),
            hostNanos(initialDelay, unit),
            hostNanos(period, unit).coerceAtLeast(1),
            TimeUnit.NANOSECONDS,
        )

    override fun scheduleWithFixedDelay(
        command: Runnable,
        initialDelay: Long,
        delay: Long,
        unit: TimeUnit,
    ): ScheduledFuture<*> =
        timer.scheduleWithFixedDelay(
            handOver(command),
            hostNanos(initialDelay, unit),
            hostNanos(delay, unit).coerceAtLeast(1),
            TimeUnit.NANOSECONDS,
        )

    /** A delay of the robot's time in nanoseconds of the host's. */
    private fun hostNanos(delay: Long, unit: TimeUnit): Long =
        unit.toNanos(delay).let { if (speed == 1.0) it else (it / speed).toLong() }

    /** [command] handed to a worker when due; cancelled, if it is a future, once the workers are shut down. */
    private fun handOver(command: Runnable) = Runnable {
        try {
            workers.execute(command)
        } catch (e: RejectedExecutionException) {
            (command as? Future<*>)?.cancel(false)
        }
    }

    /** A task whose time the timer keeps ([timed]) and whose result a worker makes ([task]). */
    private class HandedOver<V>(private val timed: ScheduledFuture<*>, private val task: FutureTask<V>) :
        ScheduledFuture<V>, Future<V> by task {
        override fun getDelay(unit: TimeUnit): Long = timed.getDelay(unit)

        override fun compareTo(other: Delayed): Int = timed.compareTo(other)

        override fun cancel(mayInterruptIfRunning: Boolean): Boolean {
            timed.cancel(false)
            return task.cancel(mayInterruptIfRunning)
        }
    }

    override fun shutdown() {
        timer.shutdown()
        workers.shutdown()
    }

    override fun shutdownNow(): List<Runnable> = timer.shutdownNow() + workers.shutdownNow()

    override fun isShutdown(): Boolean = workers.isShutdown

    override fun isTerminated(): Boolean = timer.isTerminated && workers.isTerminated

    override fun awaitTermination(timeout: Long, unit: TimeUnit): Boolean {
        val until = System.nanoTime() + unit.toNanos(timeout)
        return timer.awaitTermination(timeout, unit) &&
            workers.awaitTermination(until - System.nanoTime(), TimeUnit.NANOSECONDS)
    }
}
