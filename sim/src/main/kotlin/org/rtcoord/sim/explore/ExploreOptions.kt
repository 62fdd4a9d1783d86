package org.rtcoord.sim.explore

import kotlin.time.Duration

/**
 * How `rtcoord test --explore` searches: [seed] draws the schedules; it stops after [runs] runs or once [duration] is
 * up (the first that comes; both null: at [DEFAULT_RUNS]); each schedule has up to [maxFaults] faults; [parallelism]
 * runs go at once, each on a system of its own; a distinct failure is shrunk in at most [shrinkRuns] runs; [writeTests]
 * writes each as a regression test next to the test. The simulated systems, their trees and the coordinators run
 * [speed] times as fast as the robot's clock (`TreeConfig.speed`).
 */
public class ExploreOptions
@JvmOverloads
constructor(
    /** What the schedules are drawn from: the same seed draws the same schedules. */
    public val seed: Long,
    /** How many runs, or null for as many as [duration] allows. */
    public val runs: Int? = null,
    /** How long to explore, or null for [runs] runs. */
    public val duration: Duration? = null,
    /** The most faults a schedule has. */
    public val maxFaults: Int = DEFAULT_MAX_FAULTS,
    /** How many runs go at once. */
    public val parallelism: Int = 1,
    /** The most runs shrinking one distinct failure may take. */
    public val shrinkRuns: Int = DEFAULT_SHRINK_RUNS,
    /** Whether each distinct failure is written as `NAME.found-SEED-INDEX.test.kts` next to the test. */
    public val writeTests: Boolean = true,
    /** How many times as fast as the robot's clock each run goes. */
    public val speed: Double = DEFAULT_SPEED,
) {
    init {
        require(runs == null || runs > 0) { "--runs must be at least 1" }
        require(maxFaults >= 1) { "--max-faults must be at least 1" }
        require(parallelism >= 1) { "--parallel must be at least 1" }
        require(speed > 0 && speed.isFinite()) { "--speed must be positive" }
    }

    /** The runs to make: [runs], or [DEFAULT_RUNS] when neither it nor [duration] is given, or unbounded. */
    internal val runLimit: Long
        get() = runs?.toLong() ?: if (duration == null) DEFAULT_RUNS.toLong() else Long.MAX_VALUE

    public companion object {
        /** Runs made when neither their number nor a duration is given. */
        public const val DEFAULT_RUNS: Int = 100

        /** The most faults a schedule has unless told. */
        public const val DEFAULT_MAX_FAULTS: Int = 3

        /** The most runs shrinking one failure takes unless told. */
        public const val DEFAULT_SHRINK_RUNS: Int = 40

        /** How many times as fast as the robot's clock runs go unless told. */
        public const val DEFAULT_SPEED: Double = 10.0

        /**
         * How many runs an exploration makes at once for each processor unless told. A run at [DEFAULT_SPEED] spends
         * most of its time waiting for its clock: exploring the paper's test on 2 cores, 6 at once used 1.4 cores and
         * went 28 times as fast as the robot's clock (2 at once: 12.5), and gave each of 200 runs the verdict it had 2
         * at once (and each of 100 the one it had alone); 8 at once went no faster and moved one. A busier machine
         * moves the verdicts of timing-sensitive schedules sooner, so replaying reruns one per processor, and a failure
         * is shrunk one run at a time.
         */
        public const val RUNS_PER_PROCESSOR: Int = 3

        /** [speed] as `--speed` takes it: `10`, `2.5`. */
        public fun shown(speed: Double): String =
            if (speed % 1.0 == 0.0) speed.toLong().toString() else speed.toString()
    }
}
