package org.rtcoord

import kotlin.time.Duration
import org.rtcoord.internal.ValueFields

/**
 * How the tree learns what a component does: pushed by its ComponentObserver, read again at a period, or neither.
 * Decided when the tree starts watching the component, and again when that changes (an observer the component no longer
 * takes falls back to polling); see [WatchMethodChanged].
 */
public sealed class WatchMethod : ValueObject() {
    /**
     * The component's observer of [flavour] pushes its changes, with a heartbeat every [heartbeat] (the shortest its
     * registrations asked for, or longer in a tree watching thousands of components: see [EventOptions.heartbeat]);
     * [pollPeriod] is set when a registration asked for polling too.
     */
    public class Pushed(
        public val flavour: ObserverFlavour,
        @get:JvmSynthetic public val heartbeat: Duration,
        @get:JvmSynthetic public val pollPeriod: Duration?,
    ) : WatchMethod() {
        override fun fields(): ValueFields =
            ValueFields("flavour" to flavour, "heartbeat" to heartbeat, "pollPeriod" to pollPeriod)

        /** [heartbeat] in milliseconds, for Java callers. */
        public val heartbeatMillis: Long
            get() = heartbeat.inWholeMilliseconds

        /** [pollPeriod] in milliseconds (null when not polled), for Java callers. */
        public val pollPeriodMillis: Long?
            get() = pollPeriod?.inWholeMilliseconds
    }

    /** The component is read again every [period], because [reason]. */
    public class Polled(@get:JvmSynthetic public val period: Duration, public val reason: String) : WatchMethod() {
        override fun fields(): ValueFields = ValueFields("period" to period, "reason" to reason)

        /** [period] in milliseconds, for Java callers. */
        public val periodMillis: Long
            get() = period.inWholeMilliseconds
    }

    /** Nothing tells the tree of changes: only pushed events were asked for, and [reason]. */
    public class Unwatched(public val reason: String) : WatchMethod() {
        override fun fields(): ValueFields = ValueFields("reason" to reason)
    }
}
