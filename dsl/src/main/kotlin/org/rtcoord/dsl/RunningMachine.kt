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
 * A move of a machine: [from] (null for the start) to [to], both paths like `system/nominal/tracking`, on [trigger], at
 * [at].
 */
public class ModeTransition(
    public val from: String?,
    public val to: String,
    public val trigger: String,
    public val at: Instant,
) : ValueObject() {
    override fun fields(): ValueFields = ValueFields("from" to from, "to" to to, "trigger" to trigger, "at" to at)
}

/**
 * A [ModeMachine] as a [Coordinator] runs it: where it is, how it got there, and how many events it left unconsumed.
 * Every value is safe to read from any thread.
 */
public class RunningMachine
internal constructor(
    /** What the script declared. */
    public val model: ModeMachine
) {
    private val current = MutableStateFlow<String?>(null)
    private val moves = MutableStateFlow<List<ModeTransition>>(emptyList())
    private val unconsumedCount = MutableStateFlow(0)

    /** The machine's name. */
    public val name: String
        get() = model.name

    /** The path of the innermost active mode, `system/nominal/tracking`; null until the machine has started. */
    public val mode: StateFlow<String?> = current.asStateFlow()

    /**
     * The transitions so far, oldest first, starting with the start itself (the last [HISTORY_LIMIT] of them). Each
     * change is a new list, so a collector that is slow sees the latest complete history.
     */
    public val history: StateFlow<List<ModeTransition>> = moves.asStateFlow()

    /**
     * How many events no transition consumed: events the machine watches that came while no active mode had a
     * transition for them (or none whose guards held), `done`/`failed` nobody waited for, and timeouts or outcomes that
     * came after their mode was left. Each is also logged at debug level.
     */
    public val unconsumed: Int
        get() = unconsumedCount.value

    /** [unconsumed] as it changes, for those who show it. */
    public val unconsumedCounts: StateFlow<Int> = unconsumedCount.asStateFlow()

    internal fun moved(transition: ModeTransition) {
        moves.update { (it + transition).takeLast(HISTORY_LIMIT) }
        current.value = transition.to
    }

    internal fun notConsumed() {
        unconsumedCount.update { it + 1 }
    }

    public companion object {
        /** How many transitions [history] keeps. */
        public const val HISTORY_LIMIT: Int = 1000
    }
}
