package org.rtcoord.bench

import java.lang.management.ManagementFactory
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

    const val MB: Double = 1024.0 * 1024.0
}
