package org.rtcoord.bench

import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration.Companion.seconds
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.test.CoordinatorTestRunner

/**
 * Coordinator tests (`rtcoord test`). **Scenario overhead**: what a scenario costs beyond its own timeline, in this
 * JVM: a scenario of `examples/localisation.coord.kts` on the system simulated from `examples/localisation.xml` whose
 * timeline is one `at(1.seconds) { }`, its duration less that second: simulating the system, starting the coordinator,
 * observing both, waiting for quiet after the last step, stopping everything. **Suite**: the wall time of `./rtcoord
 * test examples/` as a user runs it, a process with its compiled tests cached.
 */
internal class TestBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    suspend fun run() {
        report.section("coordinator tests: rtcoord test on the simulated localisation system")
        if (!options.scripts) {
            listOf(OVERHEAD, SUITE).forEach {
                report.skipped(it, "coordinator scripts are not compiled in a ${options.profile} run")
            }
            return
        }
        overhead()
        suite()
    }

    private suspend fun overhead() {
        val directory = Files.createTempDirectory("bench-test")
        try {
            val examples = installation.root.resolve("examples")
            val test = directory.resolve("overhead.test.kts")
            Files.writeString(
                test,
                "system(\"${examples.resolve("localisation.xml")}\")\ncoordinator(\"${examples.resolve("localisation.coord.kts")}\")\nat(1.seconds) { }\n",
            )
            val runner =
                CoordinatorTestRunner(
                    parallelism = 1,
                    scripts = ScriptHost(installation.root.resolve("bench/target/script-cache")),
                )
            val file = runner.files(listOf(test)).single()
            // The first runs compile the test and the coordinator (or take them from the caches) and warm the JVM up.
            repeat(options.libraryWarmups) { scenario(runner, file.path) }
            val overheads = List(options.testRepetitions) { scenario(runner, file.path) - TIMELINE.inWholeNanoseconds }
            report.row(
                OVERHEAD,
                Samples.millis(overheads),
                "a fresh system, the coordinator started and stopped, 0.2 s of quiet after the last step; goal: under 1 s",
            )
        } finally {
            directory.toFile().deleteRecursively()
        }
    }

    /** Runs the scenario of [test]; its duration in nanoseconds. */
    private suspend fun scenario(runner: CoordinatorTestRunner, test: Path): Long {
        val result = runner.run(runner.files(listOf(test)).single()).single()
        check(result.passed) { "the scenario failed: ${result.failures.joinToString()}" }
        return result.duration.inWholeNanoseconds
    }

    private fun suite() {
        installation.cliMissing?.let {
            report.skipped(SUITE, it)
            return
        }
        val command =
            TimedCommand(SUITE, listOf(installation.launcher.toString(), "test", "examples/"), installation.root)
        // The first run compiles the examples' tests into the cache, as a user's first run does.
        command.run()
        val runs = List(options.suiteRepetitions) { command.run() }
        val summary = runs.last().output.lastOrNull().orEmpty()
        report.row(
            SUITE,
            Samples.seconds(runs.map { it.nanos }),
            "whole process, tests compiled and cached; last: $summary",
        )
    }

    private companion object {
        val TIMELINE = 1.seconds
        const val OVERHEAD = "scenario overhead beyond its timeline"
        const val SUITE = "rtcoord test examples/ (wall time)"
    }
}
