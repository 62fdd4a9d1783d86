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
import java.nio.file.Paths

/** `rtcoord test [FILES|DIR]`: coordinator tests, each against a fresh simulated system. */
class TestCommand : CliktCommand("test") {
    override fun help(context: Context): String =
        "Run coordinator tests (*.test.kts): each simulates the system its RTSProfile describes, runs its coordinator on it, " +
            "plays its scenario (faults at given times) and checks its expectations, each within its deadline. Tests run in " +
            "parallel, each on a system of its own. Prints a line per test and a summary; a failure names the test file's line. " +
            "Exits 1 when a test fails."

    override fun helpEpilog(context: Context): String = examples(
        "rtcoord test examples/" to "every *.test.kts in examples/",
        "rtcoord test --junit target/rtcoord-tests nav.test.kts" to "one test, with JUnit XML for CI",
    )

    private val paths by argument("FILES|DIR", help = "Test files, or directories whose *.test.kts files are run; default: the current directory.")
        .path(mustExist = true).multiple()

    private val junit by option("--junit", metavar = "DIR", help = "Also write a JUnit XML report per test into DIR.").path(canBeFile = false)

    private val parallel by option("--parallel", metavar = "N", help = "How many tests run at once; default: one per processor.").int()

    override fun run() {
        val runner = parallel?.let { CoordinatorTestRunner(parallelism = it) } ?: CoordinatorTestRunner()
        val files = try {
            runner.files(paths.ifEmpty { listOf(Paths.get("")) })
        } catch (e: IllegalArgumentException) {
            throw CommandFailed(e.message.orEmpty())
        }
        if (files.isEmpty()) throw CommandFailed("${paths.joinToString(" ").ifEmpty { "." }}: no *.test.kts files")
        val results = runBlocking { runner.runAll(files) }
        for (result in results) {
            echo("${if (result.passed) "PASS" else "FAIL"} ${result.file} (${result.duration.inWholeMilliseconds} ms)")
            result.failures.forEach { echo("  $it") }
        }
        junit?.let { JUnitXml.write(results, it) }
        val failed = results.count { !it.passed }
        echo("${results.size} tests, ${results.size - failed} passed, $failed failed")
        if (failed > 0) throw ProgramResult(1)
    }
}
