package org.rtcoord.internal.events

/**
 * Whether one watched component answers, decided from signs of life (hints and heartbeats, a read that brings it back),
 * the silence of a component whose observer should send heartbeats, and calls that fail. A read that succeeds is not a
 * sign of its observer's life: a component whose observer went quiet is lost at the limit even while it answers, and
 * its observer is attached anew. Pure: the monitor feeds it what happened and when (in milliseconds of any monotonic
 * clock), and publishes the [Change]s it returns.
 *
 * ```
 * ANSWERING --silent past the limit--> SILENT --a call fails--> UNREACHABLE
 * ANSWERING --a call fails-----------------------------------> UNREACHABLE (lost too if silent a beat)
 * SILENT, UNREACHABLE --a read succeeds--> ANSWERING
 * any --OBJECT_NOT_EXIST, or unreachable once it announced FINALIZE--> FINALIZED (final)
 * ```
 */
internal class ComponentLiveness(now: Long) {
    /** Where the component stands. */
    enum class State {
        /** It answers, and has not been silent longer than its heartbeats allow. */
        ANSWERING,

        /** Its observer has been silent past the limit; a read will tell whether it is gone. */
        SILENT,

        /** A call failed: it is a zombie, probed until it answers again. */
        UNREACHABLE,

        /** It is gone for good: its objects no longer exist. */
        FINALIZED,
    }

    /** What a step changed, for the monitor to publish. */
    sealed interface Change {
        /** It stopped giving signs of life [silentMillis] ago. */
        data class Lost(val silentMillis: Long) : Change

        /** A call failed: it is unreachable. */
        object Unreachable : Change

        /** It answers again after being silent or unreachable. */
        object Recovered : Change

        /** It is gone for good. */
        object Finalized : Change
    }

    var state: State = State.ANSWERING
        private set

    /** Whether it announced FINALIZE: its next unreachable answer is its end, not a fault. */
    var finalizing: Boolean = false
        private set

    /** When the last sign of life came: a hint, a heartbeat, or the read that brought it back. */
    var lastHeard: Long = now
        private set

    /**
     * A hint arrived at [now] (a time earlier than the last sign changes nothing): the component lives, though only a
     * read can bring it back from [State.UNREACHABLE].
     */
    fun hinted(now: Long, finalize: Boolean = false) {
        lastHeard = maxOf(lastHeard, now)
        if (finalize) finalizing = true
    }

    /** A read succeeded at [now]. */
    fun answered(now: Long): List<Change> {
        if (state != State.SILENT && state != State.UNREACHABLE) return emptyList()
        // Its silence counts anew: the observer is attached again.
        lastHeard = now
        state = State.ANSWERING
        return listOf(Change.Recovered)
    }

    /**
     * The watchdog's check at [now]; [limitMillis] is how long its observer may stay silent, null when no observer is
     * expected to speak. Returns the loss when it goes silent now.
     */
    fun checked(now: Long, limitMillis: Long?): Change.Lost? {
        if (state != State.ANSWERING || limitMillis == null || now - lastHeard <= limitMillis) return null
        state = State.SILENT
        return Change.Lost(now - lastHeard)
    }

    /**
     * A call failed at [now]: [gone] when its object no longer exists (`OBJECT_NOT_EXIST`), else [unreachable] when it
     * could not be reached at all (rather than answering too late). Its silence is told too when it lasted at least
     * [beatMillis], the interval it should speak at (null: none).
     */
    fun failed(now: Long, gone: Boolean, unreachable: Boolean, beatMillis: Long?): List<Change> =
        when {
            state == State.FINALIZED -> emptyList()
            gone || finalizing && unreachable -> {
                state = State.FINALIZED
                listOf(Change.Finalized)
            }
            state == State.UNREACHABLE -> emptyList()
            else -> {
                val silent = beatMillis != null && now - lastHeard >= beatMillis
                val lost = if (state == State.SILENT || !silent) emptyList() else listOf(Change.Lost(now - lastHeard))
                state = State.UNREACHABLE
                lost + Change.Unreachable
            }
        }
}
