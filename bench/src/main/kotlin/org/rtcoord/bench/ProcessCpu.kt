package org.rtcoord.bench

import java.time.Duration as JavaDuration
import kotlin.time.Duration
import kotlinx.coroutines.delay

/**
 * The CPU time [processes] spent per second of wall time over [window] (a launcher and the JVM it starts count
 * together).
 */
internal suspend fun cpuPerSecond(window: Duration, processes: () -> Sequence<ProcessHandle>): Double {
    fun cpu(): Long =
        processes().sumOf { handle ->
            handle.info().totalCpuDuration().map(JavaDuration::toNanos).orElseThrow {
                IllegalStateException("the CPU time of process ${handle.pid()} cannot be read")
            }
        }
    val before = cpu()
    val start = System.nanoTime()
    delay(window)
    return (cpu() - before).toDouble() / (System.nanoTime() - start)
}
