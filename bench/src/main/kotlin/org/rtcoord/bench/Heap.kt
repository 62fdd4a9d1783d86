package org.rtcoord.bench

import java.lang.management.ManagementFactory
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.delay
import kotlinx.coroutines.yield

/** The heap this JVM uses, as a benchmark reads it. */
internal object Heap {
    private val memory = ManagementFactory.getMemoryMXBean()

    /** Heap in use now, garbage included, in bytes. */
    fun used(): Long = memory.heapMemoryUsage.used

    /**
     * Heap in use by reachable objects: after full collections, once the figure stops falling. It first yields, because
     * `runBlocking`'s event loop keeps the last continuation it ran in a slot of its thread's stack, and with it
     * whatever that continuation reached: a tree closed a moment ago, all of it.
     */
    suspend fun live(): Long {
        yield()
        var previous = Long.MAX_VALUE
        repeat(5) {
            System.gc()
            Thread.sleep(100)
            val now = used()
            if (now >= previous - previous / 1000) return now
            previous = now
        }
        return previous
    }

    /**
     * What a running system keeps, rather than what it has in flight at one instant: the least of [samples] readings of
     * [live], [apart] apart. Ten thousand components watched by push are read 2500 times a second, and one reading
     * moved by 0.4 KB a component from run to run with what those reads held when it was taken.
     */
    suspend fun kept(samples: Int = 3, apart: Duration = 1.seconds): Long {
        var least = live()
        repeat(samples - 1) {
            delay(apart)
            least = minOf(least, live())
        }
        return least
    }

    const val MB: Double = 1024.0 * 1024.0
}
