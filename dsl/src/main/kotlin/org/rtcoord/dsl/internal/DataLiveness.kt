package org.rtcoord.dsl.internal

/**
 * Whether a port's data went silent or slow, from the times samples arrived and checks of the component's state (times
 * in milliseconds, from any monotonic clock). Only time while the port is tapped and its component ACTIVE counts:
 * before the tap is connected nothing can arrive (connecting it can take longer than a silence limit on a loaded
 * machine), and a component not ACTIVE is expected to send nothing; silence starts when the port is tapped, tapped
 * again (its component re-created) or seen ACTIVE again. Each silence or drop is reported once; a sample (or a rate
 * back at its floor) ends it.
 */
internal class DataLiveness(
    private val silenceMillis: Long?,
    private val minRate: Double?,
    private val windowMillis: Long = 1000,
) {
    private var lastSample = 0L
    /** Since when silence and rate count; null until the port is [tapped]. */
    private var countingSince: Long? = null
    private val arrivals = ArrayDeque<Long>()
    private var silentReported = false
    private var slowReported = false

    /** The port was tapped, or tapped again, at [now]: what the silence and the rate count starts then. */
    fun tapped(now: Long) {
        countingSince = now
        silentReported = false
        slowReported = false
        arrivals.clear()
    }

    fun sample(now: Long) {
        lastSample = now
        silentReported = false
        if (minRate != null) {
            arrivals.addLast(now)
            while (arrivals.isNotEmpty() && arrivals.first() <= now - windowMillis) arrivals.removeFirst()
        }
    }

    /** What a check at [now] finds, the component [active] or not. */
    fun check(now: Long, active: Boolean): Finding {
        while (arrivals.isNotEmpty() && arrivals.first() <= now - windowMillis) arrivals.removeFirst()
        val since = countingSince ?: return Finding.NOTHING
        if (!active) {
            countingSince = now
            silentReported = false
            slowReported = false
            return Finding.NOTHING
        }
        val silentFor = now - maxOf(lastSample, since)
        if (silenceMillis != null && silentFor >= silenceMillis && !silentReported) {
            silentReported = true
            return Finding.Silent(silentFor)
        }
        if (minRate != null && now - since >= windowMillis) {
            val rate = arrivals.size * 1000.0 / windowMillis
            if (rate < minRate && !slowReported) {
                slowReported = true
                return Finding.Slow(rate)
            }
            if (rate >= minRate) slowReported = false
        }
        return Finding.NOTHING
    }

    /** The outcome of a check. */
    sealed class Finding {
        object NOTHING : Finding()

        data class Silent(val millis: Long) : Finding()

        data class Slow(val rate: Double) : Finding()
    }
}
