package org.rtcoord.bench

import java.lang.management.ManagementFactory

/**
 * The time this JVM's JIT compilers have spent compiling, summed over their threads. On two cores a C2 compilation
 * takes one for tens to hundreds of milliseconds, and a woken ORB thread waits for the other: a latency measured while
 * it runs measures the JIT's warm-up, not the library.
 */
internal object JitCompilation {
    private val bean = ManagementFactory.getCompilationMXBean()

    /** Milliseconds compiled so far, or null when this JVM does not count them. */
    fun millis(): Long? = bean?.takeIf { it.isCompilationTimeMonitoringSupported }?.totalCompilationTime

    /** Runs [block]; returns its value, how long it took and how long the JIT compiled meanwhile. */
    inline fun <T> during(block: () -> T): Stretch<T> {
        val compiledBefore = millis()
        val started = System.nanoTime()
        val value = block()
        val elapsed = (System.nanoTime() - started) / 1_000_000
        return Stretch(value, elapsed, compiledBefore?.let { before -> millis()?.minus(before) })
    }

    /**
     * A stretch of work: its [value], its [millis], and the [compiledMillis] the JIT spent in it (null when not
     * counted).
     */
    class Stretch<T>(val value: T, val millis: Long, val compiledMillis: Long?)
}
