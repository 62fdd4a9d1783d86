package org.rtcoord.bench

import java.lang.management.ManagementFactory

/** The heap this JVM uses, as a benchmark reads it. */
internal object Heap {
    private val memory = ManagementFactory.getMemoryMXBean()

    /** Heap in use now, garbage included, in bytes. */
    fun used(): Long = memory.heapMemoryUsage.used

    /** Heap in use by reachable objects: after full collections, once the figure stops falling. */
    fun live(): Long {
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
