package org.rtcoord.internal.logs

/**
 * Counts one connection's entries in windows of a second, to refuse a flood: more than [maxPerSecond] in one window. A
 * window starts with the first entry after the last one ended, so a sender that keeps under the rate is never refused,
 * and one that bursts twice the rate across two windows' edge is let through once, which is enough to stop a runaway
 * sender without a clock per entry. Not thread-safe: one connection's reader owns it.
 */
internal class EntryRate(private val maxPerSecond: Int, private val nanoTime: () -> Long = System::nanoTime) {
    private var windowStart = 0L
    private var count = 0
    private var started = false

    /** Counts one entry; false when it is one too many for its window. */
    fun admit(): Boolean {
        val now = nanoTime()
        if (!started || now - windowStart >= NANOS_PER_SECOND) {
            started = true
            windowStart = now
            count = 0
        }
        count++
        return count <= maxPerSecond
    }

    private companion object {
        const val NANOS_PER_SECOND = 1_000_000_000L
    }
}
