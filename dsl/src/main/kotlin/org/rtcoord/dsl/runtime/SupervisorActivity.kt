package org.rtcoord.dsl.runtime

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.update
import java.time.Instant
import kotlin.time.Duration

/**
 * What one supervisor of a running [Coordinator] has done: its children where they are now, its
 * restarts and the back-off it waits out. Safe to read from any thread; each change is a new [Status].
 */
public class SupervisorActivity internal constructor(
    /** The supervisor's name. */
    public val name: String,
    /** How it restarts, `ONE_FOR_ONE` and so on. */
    public val strategy: String,
) {
    /** A supervisor's record at one moment. */
    public data class Status(
        /** Its children's paths, in declared order (a re-created child's new path). */
        val children: List<String> = emptyList(),
        /** How many children it restarted. */
        val restarts: Int = 0,
        /** When it last restarted a child, and which one. */
        val lastRestart: Instant? = null,
        val lastRestarted: String? = null,
        /** The back-off it is waiting out before the next restart, and until when; null when not waiting. */
        @get:JvmName("getBackoff")
        val backoff: Duration? = null,
        val waitingUntil: Instant? = null,
        /** Why it gave up, once it escalated. */
        val escalation: String? = null,
    )

    private val current = MutableStateFlow(Status())

    /** The supervisor's record so far. */
    public val status: StateFlow<Status> = current.asStateFlow()

    internal fun children(paths: List<String>) {
        current.update { it.copy(children = paths) }
    }

    internal fun waiting(backoff: Duration) {
        current.update { it.copy(backoff = backoff, waitingUntil = Instant.now().plusMillis(backoff.inWholeMilliseconds)) }
    }

    internal fun restarted(child: String, children: List<String>) {
        current.update { it.copy(children = children, restarts = it.restarts + 1, lastRestart = Instant.now(), lastRestarted = child, backoff = null, waitingUntil = null) }
    }

    internal fun escalated(reason: String) {
        current.update { it.copy(escalation = reason, backoff = null, waitingUntil = null) }
    }
}
