package org.rtcoord.bench

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds

/** The benchmarks, by the names `--only` takes, in the order a run does them. */
internal enum class Benchmark(val label: String) {
    MICRO("micro"),
    DISCOVERY("discovery"),
    REACTION("reaction"),
    MONITORING("monitoring"),
    ROUNDTRIP("roundtrip"),
    MEMORY("memory"),
    STARTUP("startup"),
    PROFILE("profile"),
    DATA("data"),
    TEST("test"),
    SIMULATION("simulation"),
    EXPLORE("explore"),
    LOGS("logs"),
}

/**
 * How big and how long: the full run measures what issue 9 asks for; [quick] the same things smaller and shorter;
 * [smoke] tiny, only to show the harness works (the unit test runs it). Repetitions and warm-ups are per measured
 * quantity; [seed] fixes every random pause.
 */
internal data class BenchOptions(
    val profile: String,
    val benchmarks: List<Benchmark>,
    val discoverySizes: List<Int>,
    /** Untimed runs of each command before the timed ones: file cache, class-data archives, JIT caches. */
    val processWarmups: Int,
    /** Timed runs of each command at size N. */
    val processRepetitions: (Int) -> Int,
    /**
     * Most components read by untimed library discoveries before the timed ones, if the JIT is not quiet sooner: a JVM
     * that still compiles the discovery path is not the warm one the row is about.
     */
    val libraryWarmUpLimit: Int,
    /** Untimed runs before the timed ones of what rtctree, the simulation and the test runner time. */
    val libraryWarmups: Int,
    val libraryRepetitions: Int,
    val reactionChanges: Int,
    /** Most untimed push changes before the timed ones, if the JIT is not quiet sooner. */
    val reactionWarmUpLimit: Int,
    val monitoredComponents: Int,
    val monitoringWindow: Duration,
    val monitoringWarmup: Duration,
    /** Components watched by push in the monitoring benchmark's section at scale. */
    val pushScaleComponents: Int = 10_000,
    val roundTripRepetitions: Int,
    /** Tree sizes to try for the memory benchmark, largest first: the first the machine can serve counts. */
    val memorySizes: List<Int>,
    val memoryRepetitions: Int,
    /** Profile reads for the discovery floor: one at a time, then all callers at once. */
    val floorCalls: Pair<Int, Int>,
    val startupRepetitions: Int,
    /** Components in the system whose profile is restored (N - 1 connections). */
    val profileSize: Int,
    /** Timed restores of each kind. */
    val profileRepetitions: Int,
    /** JMH iterations of each microbenchmark: warm-up, measured. */
    val microIterations: Pair<Int, Int>,
    /** How long one JMH iteration runs. */
    val microIteration: Duration,
    /** Whether to time the coordinator scripts (round trip, cached script start): they compile the script once. */
    val scripts: Boolean,
    val seed: Long = 9,
    /** How long the data benchmark counts at each rate, with its tap and without. */
    val dataWindow: Duration = 10.seconds,
    /** Most windows the simulated out-port writes before it is measured, until the JIT is quiet (at least three). */
    val portWarmUpWindows: Int = 30,
    /**
     * Pairs of windows (writing, then inactive) the simulated out-port is measured in: the machine's noise moves one 10
     * s window by a quarter of the cost.
     */
    val portRounds: Int = 5,
    /** Silences timed at each threshold. */
    val silenceRepetitions: Int = 5,
    /** Timed scenarios of the coordinator test's overhead. */
    val testRepetitions: Int = 10,
    /** Timed runs of `rtcoord test examples/`. */
    val suiteRepetitions: Int = 3,
    /** Components in the simulated system whose start is timed. */
    val simulationSize: Int = 200,
    /** Timed starts of the simulated system, each kind. */
    val simulationRepetitions: Int = 10,
    /** Runs of `rtcoord test --explore` per processor used. */
    val exploreRuns: Int = 60,
    /** Connections sending log records, all together at [logRate] records a second. */
    val logSenders: Int = 100,
    val logRate: Int = 10_000,
    /** How long the log records' CPU is sampled, after [logWarmup] at the same rate. */
    val logWindow: Duration = 10.seconds,
    val logWarmup: Duration = 5.seconds,
    /** The longest warm-up of the log records, waiting for the JIT to be quiet. */
    val logWarmupLimit: Duration = 40.seconds,
    /** Records sent while a slow view holds its first one. */
    val logFlood: Int = 200_000,
) {
    companion object {
        const val USAGE =
            """usage: scripts/bench [--quick] [--only NAME,...] [--seconds S] [--launcher-jvm]

Runs rtcoord's benchmarks and prints one table (min/median/max, ratios against rtshell and rtctree measured
in the same run). Results are printed, never stored.
  --quick       smaller systems, fewer repetitions, 10 s monitoring windows (a few minutes in all)
  --only        some of: micro, discovery, reaction, monitoring, roundtrip, memory, startup, profile, data, test, simulation, explore, logs
  --seconds S   the monitoring window (default 60, quick 10)
  --launcher-jvm  the benchmarks' JVM takes the options the rtcoord launcher gives its commands (C1 only),
                not the JDK's defaults (C1 then C2, as a host application embedding the library runs)"""

        /** What issue 9 asks for: N up to 1000 (10,000 for memory), 60 s monitoring windows. */
        fun full(benchmarks: List<Benchmark>): BenchOptions =
            BenchOptions(
                profile = "full",
                benchmarks = benchmarks,
                discoverySizes = listOf(10, 100, 1000),
                processWarmups = 1,
                processRepetitions = { n -> if (n >= 1000) 5 else 10 },
                libraryWarmUpLimit = 5000,
                libraryWarmups = 3,
                libraryRepetitions = 10,
                reactionChanges = 1000,
                reactionWarmUpLimit = 20_000,
                monitoredComponents = 1000,
                monitoringWindow = 60.seconds,
                monitoringWarmup = 10.seconds,
                roundTripRepetitions = 10,
                memorySizes = listOf(10_000, 5000, 2000),
                memoryRepetitions = 3,
                floorCalls = 2000 to 20_000,
                startupRepetitions = 10,
                profileSize = 200,
                profileRepetitions = 10,
                microIterations = 5 to 5,
                microIteration = 2.seconds,
                scripts = true,
            )

        /** What the full run measures, smaller and shorter. */
        fun quick(benchmarks: List<Benchmark>): BenchOptions =
            full(benchmarks)
                .copy(
                    profile = "quick",
                    discoverySizes = listOf(10, 100),
                    processRepetitions = { 3 },
                    libraryWarmUpLimit = 2000,
                    libraryWarmups = 2,
                    libraryRepetitions = 5,
                    reactionChanges = 200,
                    reactionWarmUpLimit = 4000,
                    monitoringWindow = 10.seconds,
                    monitoringWarmup = 3.seconds,
                    roundTripRepetitions = 3,
                    memorySizes = listOf(2000),
                    memoryRepetitions = 2,
                    floorCalls = 1000 to 10_000,
                    startupRepetitions = 3,
                    profileRepetitions = 3,
                    microIterations = 4 to 3,
                    microIteration = 1.seconds,
                    dataWindow = 5.seconds,
                    portRounds = 3,
                    silenceRepetitions = 3,
                    testRepetitions = 5,
                    suiteRepetitions = 1,
                    simulationRepetitions = 3,
                    exploreRuns = 20,
                )

        /** Tiny and short: the harness runs [benchmarks] end to end in well under a minute, scripts aside. */
        fun smoke(benchmarks: List<Benchmark>): BenchOptions =
            quick(benchmarks)
                .copy(
                    profile = "smoke",
                    discoverySizes = listOf(10),
                    processWarmups = 0,
                    processRepetitions = { 1 },
                    libraryWarmUpLimit = 20,
                    libraryWarmups = 1,
                    libraryRepetitions = 2,
                    reactionChanges = 20,
                    reactionWarmUpLimit = 20,
                    monitoredComponents = 10,
                    pushScaleComponents = 20,
                    monitoringWindow = 1.seconds,
                    monitoringWarmup = 500.milliseconds,
                    roundTripRepetitions = 1,
                    memorySizes = listOf(100),
                    memoryRepetitions = 1,
                    floorCalls = 50 to 200,
                    startupRepetitions = 1,
                    profileSize = 10,
                    profileRepetitions = 1,
                    microIterations = 1 to 1,
                    microIteration = 200.milliseconds,
                    scripts = false,
                    dataWindow = 500.milliseconds,
                    portWarmUpWindows = 3,
                    portRounds = 1,
                    silenceRepetitions = 1,
                    testRepetitions = 1,
                    suiteRepetitions = 1,
                    simulationSize = 10,
                    simulationRepetitions = 1,
                    exploreRuns = 1,
                    logSenders = 10,
                    logRate = 1000,
                    logWindow = 1.seconds,
                    logWarmup = 500.milliseconds,
                    logWarmupLimit = 1.seconds,
                    logFlood = 20_000,
                )

        /** Parses the command line; a problem is a one-line [IllegalArgumentException]. */
        fun parse(args: List<String>): BenchOptions {
            var quick = false
            var only: List<Benchmark> = Benchmark.values().toList()
            var seconds: Double? = null
            val rest = args.iterator()
            while (rest.hasNext()) {
                when (val arg = rest.next()) {
                    "--quick" -> quick = true
                    "--only" -> {
                        val names =
                            (if (rest.hasNext()) rest.next()
                                else throw IllegalArgumentException("--only needs a list of benchmarks"))
                                .split(',')
                                .map { it.trim() }
                                .filter { it.isNotEmpty() }
                        only = names.map { name ->
                            Benchmark.values().firstOrNull { it.label == name }
                                ?: throw IllegalArgumentException(
                                    "--only: no benchmark '$name' (there are ${Benchmark.values().joinToString { it.label }})"
                                )
                        }
                    }
                    "--seconds" ->
                        seconds =
                            (if (rest.hasNext()) rest.next() else null)?.toDoubleOrNull()?.takeIf { it > 0 }
                                ?: throw IllegalArgumentException("--seconds needs a positive number")
                    else -> throw IllegalArgumentException("unknown argument '$arg'")
                }
            }
            val chosen = Benchmark.values().filter { it in only }
            val options = if (quick) quick(chosen) else full(chosen)
            return seconds?.let { options.copy(monitoringWindow = it.seconds) } ?: options
        }
    }
}
