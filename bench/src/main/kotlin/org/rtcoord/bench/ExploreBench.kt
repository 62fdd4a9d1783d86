package org.rtcoord.bench

import java.lang.management.ManagementFactory
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.explore.ExploreOptions
import org.rtcoord.sim.explore.FaultExplorer

/**
 * Exploring faults (`rtcoord test --explore`) on `examples/localisation.test.kts`, in this JVM: schedules per minute
 * one at a time and one per processor, and the speed-up over the robot's clock (the runs' own time summed, over the
 * wall time), after one untimed exploration. The runs go at `--explore`'s default speed ([ExploreOptions.DEFAULT_SPEED]
 * times the robot's clock). Each exploration's wall time includes its baseline (each explored scenario run once without
 * faults). Shrinking and the written tests are left out: exploring alone.
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
        for (parallelism in listOf(1, processors, ExploreOptions.RUNS_PER_PROCESSOR * processors).distinct()) {
            val cpuBefore = os.processCpuTime
            val explored =
                FaultExplorer(scripts)
                    .explore(
                        test,
                        ExploreOptions(
                            seed = options.seed,
                            runs = options.exploreRuns * parallelism,
                            parallelism = parallelism,
                            shrinkRuns = 0,
                            writeTests = false,
                        ),
                    )
            val cores = (os.processCpuTime - cpuBefore) / 1e6 / explored.elapsed.inWholeMilliseconds
            val minutes = explored.elapsed.inWholeMilliseconds / 60_000.0
            report.value(
                "$ROW, $parallelism at a time",
                explored.runs / minutes,
                "/min",
                "${explored.runs} runs, ${explored.failed} failed, ${explored.skipped} skipped; " +
                    "${figure(explored.robotTime.inWholeMilliseconds / 1000.0 / explored.runs)} s of the robot's time a run; " +
                    "${figure(explored.robotTime.inWholeMilliseconds.toDouble() / explored.elapsed.inWholeMilliseconds)}x the robot's clock " +
                    "(each run at ${ExploreOptions.shown(ExploreOptions.DEFAULT_SPEED)}x); ${figure(cores * 100)} % of a core",
            )
        }
    }

    private val os = ManagementFactory.getOperatingSystemMXBean() as com.sun.management.OperatingSystemMXBean

    private companion object {
        const val ROW = "schedules explored per minute"
    }
}
