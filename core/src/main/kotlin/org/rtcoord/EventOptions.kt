package org.rtcoord

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/** Where events come from. */
public enum class WatchMode {
    /** The component's ComponentObserver when it accepts one (either flavour), else polling. */
    AUTO,

    /** The ComponentObserver only; components that accept none are not watched. */
    PUSH,

    /** Re-reading the component every [EventOptions.pollPeriod]. */
    POLL,
}

/** What happens to events that arrive while the callback is still running on an earlier one. */
public enum class Overlap {
    /** They wait their turn, in order: nothing is lost. */
    QUEUE,

    /** They are dropped until the callback returns. */
    SKIP,

    /** Only the newest waits; older ones are dropped. */
    LATEST,
}

/**
 * How a registration watches.
 *
 * @property mode push, poll, or push where possible.
 * @property pollPeriod how often polled components are re-read; a component watched at several periods
 *   is read at the shortest, once per tick however many registrations share it.
 * @property overlap the callback's policy for events arriving while it runs.
 * @property heartbeat the ComponentObserver heartbeat interval asked for.
 * @property missedBeats how many heartbeats may be missed before the component is presumed dead.
 */
public class EventOptions(
    public val mode: WatchMode = WatchMode.AUTO,
    public val pollPeriod: Duration = 1.seconds,
    public val overlap: Overlap = Overlap.QUEUE,
    public val heartbeat: Duration = 1.seconds,
    public val missedBeats: Int = 3,
) {
    init {
        require(pollPeriod.isPositive()) { "pollPeriod must be positive, was $pollPeriod" }
        require(heartbeat.isPositive()) { "heartbeat must be positive, was $heartbeat" }
        require(missedBeats > 0) { "missedBeats must be positive, was $missedBeats" }
    }
}

/** A registration; cancelling it stops its callback and, with the last one, the watching. */
public fun interface Subscription : AutoCloseable {
    /** Stops the registration. Idempotent. */
    public fun cancel()

    override fun close(): Unit = cancel()
}
