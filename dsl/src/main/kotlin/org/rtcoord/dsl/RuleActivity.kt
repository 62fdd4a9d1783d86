@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl

import java.time.Instant
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/**
 * What one rule of a running [Coordinator] has done: how often it fired, when last, and how its handler failed. Safe to
 * read from any thread; each change is a new [Status].
 */
public class RuleActivity
internal constructor(
    /** The rule as the script declared it, `component laser0.rtc: state ERROR`. */
    public val description: String
) {
    /** A rule's record at one moment; each change is a new one. */
    public class Status(
        /** How often its handler ran. */
        public val firings: Int = 0,
        /** When its handler last started, null before the first firing. */
        public val lastFired: Instant? = null,
        /** What fired it last: the event's type and source. */
        public val lastEvent: String? = null,
        /** How many handler runs failed. */
        public val failures: Int = 0,
        /** The last failure's message. */
        public val lastFailure: String? = null,
        /** How many of its handler runs have started and not returned yet. */
        public val running: Int = 0,
    ) : ValueObject() {
        @JvmSynthetic
        internal fun copy(
            firings: Int = this.firings,
            lastFired: Instant? = this.lastFired,
            lastEvent: String? = this.lastEvent,
            failures: Int = this.failures,
            lastFailure: String? = this.lastFailure,
            running: Int = this.running,
        ): Status = Status(firings, lastFired, lastEvent, failures, lastFailure, running)

        override fun fields(): ValueFields =
            ValueFields(
                "firings" to firings,
                "lastFired" to lastFired,
                "lastEvent" to lastEvent,
                "failures" to failures,
                "lastFailure" to lastFailure,
                "running" to running,
            )
    }

    private val current = MutableStateFlow(Status())

    /** The rule's record so far. */
    public val status: StateFlow<Status> = current.asStateFlow()

    internal fun fired(event: String) {
        current.update {
            it.copy(firings = it.firings + 1, lastFired = Instant.now(), lastEvent = event, running = it.running + 1)
        }
    }

    internal fun returned() {
        current.update { it.copy(running = it.running - 1) }
    }

    internal fun failed(message: String) {
        current.update { it.copy(failures = it.failures + 1, lastFailure = message) }
    }
}
