package org.rtcoord

import kotlin.time.Duration

/**
 * How the tree learns what a component does: pushed by its ComponentObserver, read again at a period,
 * or neither. Decided when the tree starts watching the component, and again when that changes (an
 * observer the component no longer takes falls back to polling); see [WatchMethodChanged].
 */
public sealed class WatchMethod {
    /**
     * The component's observer of [flavour] pushes its changes, with a heartbeat every [heartbeat];
     * [pollPeriod] is set when a registration asked for polling too.
     */
    public data class Pushed(val flavour: ObserverFlavour, @get:JvmSynthetic val heartbeat: Duration, @get:JvmSynthetic val pollPeriod: Duration?) : WatchMethod() {
        /** [heartbeat] in milliseconds, for Java callers. */
        public val heartbeatMillis: Long get() = heartbeat.inWholeMilliseconds

        /** [pollPeriod] in milliseconds (null when not polled), for Java callers. */
        public val pollPeriodMillis: Long? get() = pollPeriod?.inWholeMilliseconds
    }

    /** The component is read again every [period], because [reason]. */
    public data class Polled(@get:JvmSynthetic val period: Duration, val reason: String) : WatchMethod() {
        /** [period] in milliseconds, for Java callers. */
        public val periodMillis: Long get() = period.inWholeMilliseconds
    }

    /** Nothing tells the tree of changes: only pushed events were asked for, and [reason]. */
    public data class Unwatched(val reason: String) : WatchMethod()
}
