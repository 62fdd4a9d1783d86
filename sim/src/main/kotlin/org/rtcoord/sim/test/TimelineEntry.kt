package org.rtcoord.sim.test

import java.util.Locale
import kotlin.time.Duration

/**
 * One thing that happened in a scenario: a fault it injected, a line the coordinator logged, an event of the system, a
 * mode the coordinator's machine entered, or a step of the test that held or failed; [at] is its time from the
 * scenario's start (the coordinator's start; negative while it started).
 */
public class TimelineEntry
internal constructor(
    /** When, from the scenario's start. */
    public val at: Duration,
    /** What kind of thing happened. */
    public val kind: Kind,
    /** What happened, in one line. */
    public val text: String,
) {
    /** What a [TimelineEntry] tells of. */
    public enum class Kind {
        /** A fault an `at` step injected. */
        FAULT,

        /** A line the coordinator logged. */
        LOG,

        /** An event of the simulated system, as the coordinator's tree saw it. */
        EVENT,

        /** A mode the coordinator's machine entered. */
        MODE,

        /** A step of the test that held or failed. */
        STEP,
    }

    /** ` 3.012 s fault breakDown laser0`. */
    override fun toString(): String = "${seconds(at).padStart(9)}  ${kind.name.lowercase().padEnd(5)}  $text"

    internal companion object {
        /** [time] in seconds with milliseconds, as the timeline and failures show times: `3.012 s`. */
        fun seconds(time: Duration): String = String.format(Locale.ROOT, "%.3f s", time.inWholeMilliseconds / 1000.0)
    }
}
