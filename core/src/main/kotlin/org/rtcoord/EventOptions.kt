package org.rtcoord

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlin.time.toKotlinDuration

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
 * @property pollPeriod how often polled components are re-read; a component watched at several periods is read at the
 *   shortest, once per tick however many registrations share it.
 * @property overlap the callback's policy for events arriving while it runs.
 * @property heartbeat the ComponentObserver heartbeat interval asked for. A tree watching more than 2500 components
 *   asks no observer to beat more often than the power of two seconds that keeps their heartbeats under 2500 a second
 *   (4 s at 10,000): each is a call its ORB takes. [WatchMethod.Pushed.heartbeat] says which interval a component got.
 * @property missedBeats how many heartbeats may be missed before the component is presumed dead.
 * @property trafficInterval the least time between two [PortTraffic] events of one port, as the observer asks the
 *   component (`port_profile.send_event.min_interval`, `receive_event.min_interval`).
 *
 * Java callers write `new EventOptions()` for the defaults, or use a [Builder]: `new
 * EventOptions.Builder().mode(WatchMode.POLL).build()`.
 */
public class EventOptions(
    public val mode: WatchMode = WatchMode.AUTO,
    @get:JvmSynthetic public val pollPeriod: Duration = 1.seconds,
    public val overlap: Overlap = Overlap.QUEUE,
    @get:JvmSynthetic public val heartbeat: Duration = 1.seconds,
    public val missedBeats: Int = 3,
    @get:JvmSynthetic public val trafficInterval: Duration = 1.seconds,
) {
    /** The defaults: push where possible, else polling every second; events queued; a one-second heartbeat. */
    public constructor() : this(WatchMode.AUTO)

    /** [pollPeriod] in milliseconds, for Java callers. */
    public val pollPeriodMillis: Long
        get() = pollPeriod.inWholeMilliseconds

    /** [heartbeat] in milliseconds, for Java callers. */
    public val heartbeatMillis: Long
        get() = heartbeat.inWholeMilliseconds

    /** [trafficInterval] in milliseconds, for Java callers. */
    public val trafficIntervalMillis: Long
        get() = trafficInterval.inWholeMilliseconds

    init {
        require(pollPeriod.isPositive()) { "pollPeriod must be positive, was $pollPeriod" }
        require(heartbeat.isPositive()) { "heartbeat must be positive, was $heartbeat" }
        require(missedBeats > 0) { "missedBeats must be positive, was $missedBeats" }
        require(!trafficInterval.isNegative()) { "trafficInterval must not be negative, was $trafficInterval" }
    }

    /**
     * A [Builder] holding these options, to change some and keep the rest:
     * `options.newBuilder().overlap(Overlap.QUEUE).build()`.
     */
    public fun newBuilder(): Builder = Builder(this)

    /**
     * Builds [EventOptions] step by step, for Java callers: `new EventOptions.Builder().mode(WatchMode.POLL).build()`;
     * from [from]'s values, the defaults unless given.
     */
    public class Builder @JvmOverloads constructor(from: EventOptions = EventOptions()) {
        private var mode = from.mode
        private var pollPeriod: Duration = from.pollPeriod
        private var overlap = from.overlap
        private var heartbeat: Duration = from.heartbeat
        private var missedBeats = from.missedBeats
        private var trafficInterval: Duration = from.trafficInterval

        /** Sets [EventOptions.mode]. */
        public fun mode(mode: WatchMode): Builder = apply { this.mode = mode }

        /** Sets [EventOptions.pollPeriod]. */
        public fun pollPeriod(period: java.time.Duration): Builder = apply { pollPeriod = period.toKotlinDuration() }

        /** Sets [EventOptions.overlap]. */
        public fun overlap(overlap: Overlap): Builder = apply { this.overlap = overlap }

        /** Sets [EventOptions.heartbeat]. */
        public fun heartbeat(interval: java.time.Duration): Builder = apply { heartbeat = interval.toKotlinDuration() }

        /** Sets [EventOptions.missedBeats]. */
        public fun missedBeats(beats: Int): Builder = apply { missedBeats = beats }

        /** Sets [EventOptions.trafficInterval]. */
        public fun trafficInterval(interval: java.time.Duration): Builder = apply {
            trafficInterval = interval.toKotlinDuration()
        }

        /** The options; fails as the constructor does on a bad value. */
        public fun build(): EventOptions =
            EventOptions(mode, pollPeriod, overlap, heartbeat, missedBeats, trafficInterval)
    }
}

/** A registration; cancelling it stops its callback and, with the last one, the watching. */
public fun interface Subscription : AutoCloseable {
    /** Stops the registration. Idempotent. */
    public fun cancel()

    override fun close(): Unit = cancel()
}
