@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.dsl

import java.time.Instant
import kotlin.time.Duration
import kotlin.time.toJavaDuration
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.ValueObject
import org.rtcoord.internal.ValueFields

/**
 * What one supervisor of a running [Coordinator] has done: its children where they are now, its restarts and the
 * back-off it waits out. Safe to read from any thread; each change is a new [Status].
 */
public class SupervisorActivity
internal constructor(
    /** The supervisor's name. */
    public val name: String,
    /** How it restarts, `ONE_FOR_ONE` and so on. */
    public val strategy: String,
) {
    /** A supervisor's record at one moment; each change is a new one. */
    public class Status
    internal constructor(
        /** Its children's paths, in declared order (a re-created child's new path). */
        public val children: List<String> = emptyList(),
        /** How many children it restarted. */
        public val restarts: Int = 0,
        /** When it last restarted a child. */
        public val lastRestart: Instant? = null,
        /** The child it last restarted. */
        public val lastRestarted: String? = null,
        /** How many times it started each child again, as the failed one or with it, by the child's path then. */
        public val restartsByChild: Map<String, Int> = emptyMap(),
        /** The back-off it is waiting out before the next restart; null when not waiting. */
        @get:JvmSynthetic public val backoff: Duration? = null,
        /** Until when it waits out [backoff]; null when not waiting. */
        public val waitingUntil: Instant? = null,
        /** Why it gave up, once it escalated. */
        public val escalation: String? = null,
    ) : ValueObject() {
        /** [backoff] for Java callers, as a `java.time.Duration`. */
        @get:JvmName("getBackoff")
        public val backoffDuration: java.time.Duration?
            get() = backoff?.toJavaDuration()

        @JvmSynthetic
        internal fun copy(
            children: List<String> = this.children,
            restarts: Int = this.restarts,
            lastRestart: Instant? = this.lastRestart,
            lastRestarted: String? = this.lastRestarted,
            restartsByChild: Map<String, Int> = this.restartsByChild,
            backoff: Duration? = this.backoff,
            waitingUntil: Instant? = this.waitingUntil,
            escalation: String? = this.escalation,
        ): Status =
            Status(children, restarts, lastRestart, lastRestarted, restartsByChild, backoff, waitingUntil, escalation)

        override fun fields(): ValueFields =
            ValueFields(
                "children" to children,
                "restarts" to restarts,
                "lastRestart" to lastRestart,
                "lastRestarted" to lastRestarted,
                "restartsByChild" to restartsByChild,
                "backoff" to backoff,
                "waitingUntil" to waitingUntil,
                "escalation" to escalation,
            )
    }

    private val current = MutableStateFlow(Status())

    /** The supervisor's record so far. */
    public val status: StateFlow<Status> = current.asStateFlow()

    internal fun children(paths: List<String>) {
        current.update { it.copy(children = paths) }
    }

    internal fun waiting(backoff: Duration) {
        current.update {
            it.copy(backoff = backoff, waitingUntil = Instant.now().plusMillis(backoff.inWholeMilliseconds))
        }
    }

    /**
     * It is starting [child] again, failed or with one that failed: counted before the start, so whoever sees the child
     * come back up finds it counted.
     */
    internal fun startingAgain(child: String) {
        current.update { status ->
            status.copy(restartsByChild = status.restartsByChild + (child to (status.restartsByChild[child] ?: 0) + 1))
        }
    }

    /** It restarted [child] (the failed ones, named together). */
    internal fun restarted(child: String, children: List<String>) {
        current.update { status ->
            status.copy(
                children = children,
                restarts = status.restarts + 1,
                lastRestart = Instant.now(),
                lastRestarted = child,
                backoff = null,
                waitingUntil = null,
            )
        }
    }

    internal fun escalated(reason: String) {
        current.update { it.copy(escalation = reason, backoff = null, waitingUntil = null) }
    }
}
