package org.rtcoord.bench

import java.lang.management.ManagementFactory

/**
 * The time this JVM's JIT compilers have spent compiling, summed over their threads. On two cores a C2
 * compilation takes one for tens to hundreds of milliseconds, and a woken ORB thread waits for the other:
 * a latency measured while it runs measures the JIT's warm-up, not the library.
 */
internal object JitCompilation {
    private val bean = ManagementFactory.getCompilationMXBean()

    /** Milliseconds compiled so far, or null when this JVM does not count them. */
    fun millis(): Long? = bean?.takeIf { it.isCompilationTimeMonitoringSupported }?.totalCompilationTime
}
