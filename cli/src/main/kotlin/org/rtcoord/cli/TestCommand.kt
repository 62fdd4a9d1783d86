package org.rtcoord.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.Context
import com.github.ajalt.clikt.core.ProgramResult
import com.github.ajalt.clikt.parameters.arguments.argument
import com.github.ajalt.clikt.parameters.arguments.multiple
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.int
import com.github.ajalt.clikt.parameters.types.path
import kotlinx.coroutines.runBlocking
import org.rtcoord.sim.test.CoordinatorTestRunner
import org.rtcoord.sim.test.JUnitXml
import org.rtcoord.sim.test.TestReport
import java.nio.file.Paths
import java.util.Locale
import kotlin.time.TimeSource

/** `rtcoord test [FILES|DIR]`: coordinator tests, each against a fresh simulated system. */
class TestCommand : CliktCommand("test") {
    override fun help(context: Context): String =
        "Run coordinator tests (*.test.kts): each scenario simulates the system its RTSProfile describes afresh, runs the " +
            "coordinator on it, injects its faults at their times, checks its expectations, each within its deadline, and its " +
            "invariants on every event. A handler of the coordinator that fails, or a rule naming what the system lacks, fails " +
            "the scenario unless it expects so. Scenarios run in parallel, each on a system of its own. Prints a line per scenario, " +
            "for each failed one why (file:line:col, with the values its condition read) and its timeline, then a summary with " +
            "the wall time. Exits 1 when a scenario fails."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord test examples/" to "every *.test.kts in examples/",
        "rtcoord test --junit target/rtcoord-tests nav.test.kts" to "one test file, with JUnit XML for CI",
        "rtcoord test --parallel 4 tests/" to "every *.test.kts below tests/, four scenarios at a time",
    )

    private val paths by argument("FILES|DIR", help = "Test files, or directories whose *.test.kts files are run; default: the current directory.")
        .path(mustExist = true).multiple()

    private val junit by option("--junit", metavar = "DIR", help = "Also write a JUnit XML report per test file into DIR, a test case per scenario.")
        .path(canBeFile = false)

    private val parallel by option("--parallel", metavar = "N", help = "How many scenarios run at once; default: one per processor.").int()

    override fun run() {
        val runner = parallel?.let { CoordinatorTestRunner(parallelism = it) } ?: CoordinatorTestRunner()
        val files = try {
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
            echo("${if (result.passed) "PASS" else "FAIL"} ${result.file}$scenario (${result.duration.inWholeMilliseconds} ms)")
            if (!result.passed) (TestReport.failures(result) + TestReport.timeline(result)).forEach { echo("  $it") }
        }
        junit?.let { JUnitXml.write(results, it) }
        val failed = results.count { !it.passed }
        val seconds = String.format(Locale.ROOT, "%.1f", wall.inWholeMilliseconds / 1000.0)
        echo("${results.size} scenarios in ${files.size} files, ${results.size - failed} passed, $failed failed (wall time $seconds s)")
        if (failed > 0) throw ProgramResult(1)
    }
}
