package org.rtcoord.sim.explore

import java.nio.file.Path
import kotlin.time.Duration
import org.rtcoord.sim.test.TestFailure
import org.rtcoord.sim.test.TestFile
import org.rtcoord.sim.test.TimelineEntry

/**
 * What an exploration of [file] found: how many [runs] it made and how many [failed] or were [skipped] (each reason a
 * skip had, with how often), over [elapsed], whether it was [interrupted] before its end, and each distinct failure
 * once, in [failures].
 */
public class ExploreReport
internal constructor(
    /** The test explored. */
    public val file: TestFile,
    /** The seed its schedules were drawn from. */
    public val seed: Long,
    /** Runs made (skipped ones included). */
    public val runs: Int,
    /** Runs that failed. */
    public val failed: Int,
    /** Runs skipped because a fault of their schedule could not be applied. */
    public val skipped: Int,
    /** Why runs were skipped, each reason with how many. */
    public val skipReasons: Map<String, Int>,
    /** How long it explored, shrinking included. */
    public val elapsed: Duration,
    /**
     * The runs' own time summed: from each run's coordinator start to its last entry, the time the robot would have
     * taken.
     */
    public val robotTime: Duration,
    /** Whether it was stopped (Ctrl-C) before its runs or its time were done. */
    public val interrupted: Boolean,
    /** Each distinct failure (by where it fails), in the order found. */
    public val failures: List<FoundFailure>,
)

/**
 * A distinct failure an exploration found: where and how it fails ([failure]), how many runs failed so, the schedule of
 * the first ([drawn], run [firstRun]) and the smallest that still fails so ([smallest]), the command that replays it,
 * and the regression [test] written for it (with whether it failed when run as written).
 */
public class FoundFailure
internal constructor(
    /** The first run's failure: where (`file:line:col`) and what, with what explains it. */
    public val failure: TestFailure,
    /** The scenario it failed in. */
    public val scenario: String,
    /** How many runs failed at the same place. */
    public val occurrences: Int,
    /** `SEED:INDEX` of the first run that failed so. */
    public val firstRun: String,
    /** The first failing run's schedule: `1.230 s fail laser0, 3.400 s killManager localisation`. */
    public val drawn: String,
    /** The smallest schedule shrinking found that still fails so. */
    public val smallest: String,
    /** How many faults the smallest has. */
    public val faults: Int,
    /** How many runs shrinking took. */
    public val shrinkRuns: Int,
    /** The command that replays the first failing run. */
    public val replay: String,
    /** The regression test written, or null when none was (`--no-write`, or the exploration was interrupted). */
    public val test: Path?,
    /** Whether [test], run as written, failed: null when it was not run. */
    public val failsAsWritten: Boolean?,
    /** The timeline of the first failing run. */
    public val timeline: List<TimelineEntry>,
)

/**
 * One run done, for a progress display: its [key] (`SEED:INDEX`), [scenario], [schedule] and [verdict] (`PASS`, `FAIL
 * FILE:LINE:COL: ...`, `SKIP ...`), and the totals so far.
 */
public class ExploreProgress
internal constructor(
    /** `SEED:INDEX` of the run. */
    public val key: String,
    /** Its scenario. */
    public val scenario: String,
    /** Its schedule. */
    public val schedule: String,
    /** How it ended. */
    public val verdict: String,
    /** Runs made so far. */
    public val runs: Int,
    /** Runs failed so far. */
    public val failed: Int,
    /** Runs skipped so far. */
    public val skipped: Int,
    /** Distinct failures so far. */
    public val distinct: Int,
    /** Time since the exploration began. */
    public val elapsed: Duration,
) {
    /** Runs per minute so far. */
    public val perMinute: Double
        get() = if (elapsed.isPositive()) runs * 60_000.0 / elapsed.inWholeMilliseconds else 0.0
}

/**
 * [reruns] runs of one schedule, run [key] of a test: its [schedule], each run's verdict, and the share of runs that
 * agree with the most common verdict, [agreement].
 */
public class ReplayReport
internal constructor(
    /** `SEED:INDEX`. */
    public val key: String,
    /** The scenario run. */
    public val scenario: String,
    /** The schedule replayed. */
    public val schedule: String,
    /** How many times it was run. */
    public val reruns: Int,
    /** Each run's verdict, in order. */
    public val verdicts: List<String>,
    /** The most common verdict. */
    public val verdict: String,
    /** How many runs had [verdict]. */
    public val agreeing: Int,
    /** The first failing run's failures and timeline, for the console; empty when none failed. */
    public val failureLines: List<String>,
    /** How long the reruns took. */
    public val elapsed: Duration,
) {
    /** Whether the most common verdict is a failure. */
    public val failed: Boolean
        get() = verdict.startsWith("FAIL")

    /** [agreeing] of [reruns]. */
    public val agreement: Double
        get() = agreeing.toDouble() / reruns
}

/** A test that cannot be explored, and why: [lines], one a problem (`file:line:col: what`). */
public class ExploreRefused internal constructor(public val lines: List<String>) : Exception(lines.joinToString("\n"))
