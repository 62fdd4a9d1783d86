package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.options.check
import com.github.ajalt.clikt.parameters.options.default
import com.github.ajalt.clikt.parameters.options.flag
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.double
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.long
import com.github.ajalt.clikt.parameters.types.path
import java.nio.file.Paths
import java.util.Locale
import kotlin.random.Random
import kotlin.time.TimeSource
import kotlinx.coroutines.runBlocking
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.explore.ExploreOptions
import org.rtcoord.sim.test.CoordinatorTestRunner
import org.rtcoord.sim.test.JUnitXml
import org.rtcoord.sim.test.TestReport

/** `rtcoord test [FILES|DIR]`: coordinator tests, each against a fresh simulated system. */
class TestCommand : CliktCommand("test") {
    override fun help(context: Context): String =
        "Run coordinator tests (*.test.kts): each scenario simulates the system its RTSProfile describes afresh, runs the " +
            "coordinator on it, injects its faults at their times, checks its expectations, each within its deadline, and its " +
            "invariants on every event. A handler of the coordinator that fails, or a rule naming what the system lacks, fails " +
            "the scenario unless it expects so. Scenarios run in parallel, each on a system of its own. Prints a line per scenario, " +
            "for each failed one why (file:line:col, with the values its condition read) and its timeline, then a summary with " +
            "the wall time. Exits 1 when a scenario fails."

    override fun helpEpilog(context: Context): String =
        examples(
            "rtcoord test examples/" to "every *.test.kts in examples/",
            "rtcoord test --junit target/rtcoord-tests nav.test.kts" to "one test file, with JUnit XML for CI",
            "rtcoord test --parallel 4 tests/" to "every *.test.kts below tests/, four scenarios at a time",
            "rtcoord test --explore --runs 200 nav.test.kts" to "200 runs, each with faults drawn from a random seed",
            "rtcoord test --explore --for 10m --seed 42 --parallel 2 nav.test.kts" to
                "explore for 10 minutes, two runs at a time",
            "rtcoord test --speed 5 tests/" to "every scenario five times as fast as the robot's clock",
            "rtcoord test --explore --replay 42:17 nav.test.kts" to "run 17 of seed 42 again",
            "rtcoord test --explore --replay 42:17 --reruns 100 nav.test.kts" to
                "run it 100 times: how often it fails the same way",
        )

    private val paths by
        argument(
                "FILES|DIR",
                help = "Test files, or directories whose *.test.kts files are run; default: the current directory.",
            )
            .path(mustExist = true)
            .multiple()

    private val junit by
        option(
                "--junit",
                metavar = "DIR",
                help = "Also write a JUnit XML report per test file into DIR, a test case per scenario.",
            )
            .path(canBeFile = false)

    private val parallel by
        option(
                "--parallel",
                metavar = "N",
                help =
                    "How many scenarios (with --explore: runs) go at once; default: one per processor, and " +
                        "${ExploreOptions.RUNS_PER_PROCESSOR} per processor when exploring (not replaying).",
            )
            .int()

    private val explore by
        option(
                "--explore",
                help =
                    "Search fault schedules: each run draws up to --max-faults faults (fail, breakDown, repair, freeze, hang, exit, " +
                        "loseConnectors, killManager, restartNaming) on the test's components and managers, at moments within its scenario, " +
                        "and applies them alongside its steps; a run fails as the test would. Each distinct failure is shrunk to its smallest " +
                        "schedule and written as NAME.found-SEED-INDEX.test.kts. The test's explore { } narrows the search. One test file.",
            )
            .flag()

    private val runs by
        option(
                "--runs",
                metavar = "N",
                help = "With --explore: how many runs; default: ${ExploreOptions.DEFAULT_RUNS} unless --for is given.",
            )
            .int()

    private val during by
        option("--for", metavar = "DURATION", help = "With --explore: how long to explore, e.g. 10m.").duration()

    private val seed by
        option(
                "--seed",
                metavar = "S",
                help = "With --explore: the seed schedules are drawn from; default: a new one, printed.",
            )
            .long()

    private val maxFaults by
        option(
                "--max-faults",
                metavar = "K",
                help = "With --explore: the most faults a run has; default: ${ExploreOptions.DEFAULT_MAX_FAULTS}.",
            )
            .int()
            .default(ExploreOptions.DEFAULT_MAX_FAULTS)

    private val replay by
        option(
            "--replay",
            metavar = "SEED:INDEX",
            help =
                "With --explore: run that schedule again (as a run's line shows it), with the --max-faults it was drawn with.",
        )

    private val reruns by
        option("--reruns", metavar = "N", help = "With --replay: run it N times and print how many agree; default: 1.")
            .int()
            .default(1)

    private val speed by
        option(
                "--speed",
                metavar = "K",
                help =
                    "Run scenarios K times as fast as the robot's clock: the simulated system, its tree and the coordinator, with " +
                        "every timer, heartbeat, deadline and back-off; times are still shown in the robot's. Default: 1, and " +
                        "${ExploreOptions.shown(ExploreOptions.DEFAULT_SPEED)} with --explore and --replay.",
            )
            .double()
            .check("must be positive") { it > 0 && it.isFinite() }

    private val noWrite by
        option("--no-write", help = "With --explore: do not write the regression tests of what was found.").flag()

    override fun run() {
        CompilerJars.require("rtcoord test")
        if (explore || replay != null) return exploreFaults()
        val runner =
            CoordinatorTestRunner(parallel ?: Runtime.getRuntime().availableProcessors(), ScriptHost(), speed ?: 1.0)
        val files =
            try {
                runner.files(paths.ifEmpty { listOf(Paths.get("")) })
            } catch (e: IllegalArgumentException) {
                throw CommandFailed(e.message.orEmpty())
            }
        if (files.isEmpty()) throw CommandFailed("${paths.joinToString(" ").ifEmpty { "." }}: no *.test.kts files")
        val began = TimeSource.Monotonic.markNow()
        val results = runBlocking { runner.runAll(files) }
        val wall = began.elapsedNow()
        for (result in results) {
            val scenario = if (result.scenario == result.file.name) "" else " › ${result.scenario}"
            echo(
                "${if (result.passed) "PASS" else "FAIL"} ${result.file}$scenario (${result.duration.inWholeMilliseconds} ms)"
            )
            if (!result.passed) (TestReport.failures(result) + TestReport.timeline(result)).forEach { echo("  $it") }
        }
        junit?.let { JUnitXml.write(results, it) }
        val failed = results.count { !it.passed }
        val seconds = String.format(Locale.ROOT, "%.1f", wall.inWholeMilliseconds / 1000.0)
        echo(
            "${results.size} scenarios in ${files.size} files, ${results.size - failed} passed, $failed failed (wall time $seconds s)"
        )
        if (failed > 0) throw ProgramResult(1)
    }

    private val exploringSpeed: Double
        get() = speed ?: ExploreOptions.DEFAULT_SPEED

    private fun exploreFaults() {
        val file = paths.singleOrNull() ?: throw CommandFailed("--explore: give one test file (${paths.size} given)")
        val status =
            if (System.console() != null)
                StatusLine {
                    System.err.print(it)
                    System.err.flush()
                }
            else null
        val exploration = TestExploration(::echo, status)
        val processors = Runtime.getRuntime().availableProcessors()
        val failed =
            replay?.let { exploration.replay(file, it, maxFaults, reruns, parallel ?: processors, exploringSpeed) }
                ?: try {
                    exploration.explore(
                        file,
                        ExploreOptions(
                            seed ?: Random.nextLong(0, 1_000_000),
                            runs,
                            during,
                            maxFaults,
                            parallel ?: (ExploreOptions.RUNS_PER_PROCESSOR * processors),
                            writeTests = !noWrite,
                            speed = exploringSpeed,
                        ),
                        junit,
                    )
                } catch (e: IllegalArgumentException) {
                    throw CommandFailed(e.message.orEmpty())
                }
        if (failed) throw ProgramResult(1)
    }
}
