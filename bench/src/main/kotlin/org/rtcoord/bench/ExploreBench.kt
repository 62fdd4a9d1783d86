package org.rtcoord.bench

import java.lang.management.ManagementFactory
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardCopyOption
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.explore.ExploreOptions
import org.rtcoord.sim.explore.FaultExplorer

/**
 * Exploring faults (`rtcoord test --explore`) on `examples/localisation.test.kts`, in this JVM: schedules per minute
 * one at a time, one per processor and [ExploreOptions.RUNS_PER_PROCESSOR] per processor (and so many of the same test
 * with its explored scenario lengthened to 30 s), with the CPU each used, and the speed-up over the robot's clock (the
 * runs' own time summed, over the wall time), after one untimed exploration. The runs go at `--explore`'s default speed
 * ([ExploreOptions.DEFAULT_SPEED] times the robot's clock). Each exploration's wall time includes its baseline (each
 * explored scenario run once without faults). Shrinking and the written tests are left out: exploring alone.
 */
internal class ExploreBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    suspend fun run() {
        report.section("exploring faults: rtcoord test --explore on the paper's coordinator")
        if (!options.scripts) {
            report.skipped(ROW, "coordinator scripts are not compiled in a ${options.profile} run")
            return
        }
        val test = installation.root.resolve("examples/localisation.test.kts")
        val scripts = ScriptHost(installation.root.resolve("bench/target/script-cache"))
        val processors = Runtime.getRuntime().availableProcessors()
        // The first exploration compiles the test and the coordinator (or takes them from the cache) and warms the JVM
        // up.
        FaultExplorer(scripts)
            .explore(test, ExploreOptions(seed = options.seed, runs = 1, shrinkRuns = 0, writeTests = false))
        val atOnce = ExploreOptions.RUNS_PER_PROCESSOR * processors
        for (parallelism in listOf(1, processors, atOnce).distinct()) {
            explore(scripts, test, "$ROW, $parallelism at a time", options.exploreRuns * parallelism, parallelism)
        }
        // Issue 51's aim: a hundred schedules a minute of a 30-second scenario.
        val longer = thirtySeconds(test)
        if (longer == null) {
            report.skipped(LONGER_ROW, "the paper's test no longer has the scenario and window this row lengthens")
        } else {
            explore(scripts, longer, "$LONGER_ROW, $atOnce at a time", options.exploreRuns * processors, atOnce)
        }
    }

    private suspend fun explore(scripts: ScriptHost, test: Path, row: String, runs: Int, parallelism: Int) {
        val cpuBefore = os.processCpuTime
        val explored =
            FaultExplorer(scripts)
                .explore(
                    test,
                    ExploreOptions(
                        seed = options.seed,
                        runs = runs,
                        parallelism = parallelism,
                        shrinkRuns = 0,
                        writeTests = false,
                    ),
                )
        val cores = (os.processCpuTime - cpuBefore) / 1e6 / explored.elapsed.inWholeMilliseconds
        val minutes = explored.elapsed.inWholeMilliseconds / 60_000.0
        report.value(
            row,
            explored.runs / minutes,
            "/min",
            "${explored.runs} runs, ${explored.failed} failed, ${explored.skipped} skipped; " +
                "${figure(explored.robotTime.inWholeMilliseconds / 1000.0 / explored.runs)} s of the robot's time a run; " +
                "${figure(explored.robotTime.inWholeMilliseconds.toDouble() / explored.elapsed.inWholeMilliseconds)}x the robot's clock " +
                "(each run at ${ExploreOptions.shown(ExploreOptions.DEFAULT_SPEED)}x); ${figure(cores * 100)} % of a core",
        )
    }

    /**
     * The paper's test with its explored scenario lasting 30 s (and faults in its first 28), written with the system
     * and coordinator it names into `bench/target/explore-30s`; null when the test has changed so that it cannot be.
     */
    private fun thirtySeconds(test: Path): Path? {
        val text = Files.readString(test)
        if (SCENARIO_END !in text || WINDOW !in text) return null
        val longer = text.replace(SCENARIO_END, "at(30.seconds) { }").replace(WINDOW, "window(0.seconds, 28.seconds)")
        val directory = Files.createDirectories(installation.root.resolve("bench/target/explore-30s"))
        for (name in listOf("localisation.xml", "localisation.coord.kts")) {
            Files.copy(test.resolveSibling(name), directory.resolve(name), StandardCopyOption.REPLACE_EXISTING)
        }
        return Files.writeString(directory.resolve("localisation-30s.test.kts"), longer)
    }

    private val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean

    private companion object {
        const val ROW = "schedules explored per minute"
        const val LONGER_ROW = "schedules of a 30-second scenario explored per minute"
        const val SCENARIO_END = "at(8.seconds) { }"
        const val WINDOW = "window(0.seconds, 6.seconds)"
    }
}
