package org.rtcoord.cli

import java.nio.file.Path
import java.util.Locale
import kotlin.time.Duration
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import org.rtcoord.sim.explore.ExploreJUnit
import org.rtcoord.sim.explore.ExploreOptions
import org.rtcoord.sim.explore.ExploreProgress
import org.rtcoord.sim.explore.ExploreRefused
import org.rtcoord.sim.explore.ExploreReport
import org.rtcoord.sim.explore.FaultExplorer

/**
 * `rtcoord test --explore` and `--replay` on the console: a line per run (its `SEED:INDEX`, verdict and schedule), a
 * progress line on a terminal, and at the end each distinct failure once with its smallest schedule and the command
 * that replays it. Ctrl-C ends the exploration with what it found so far.
 */
internal class TestExploration(private val echo: (String) -> Unit, private val status: StatusLine?) {
    /** Explores [file]; whether it found a failure. */
    fun explore(file: Path, options: ExploreOptions, junit: Path?): Boolean {
        val explorer = FaultExplorer()
        val limit =
            listOfNotNull(options.runs?.let { "$it runs" }, options.duration?.let { "for $it" }).ifEmpty {
                listOf("${ExploreOptions.DEFAULT_RUNS} runs")
            }
        echo(
            "exploring $file: seed ${options.seed}, ${limit.joinToString(" or ")}, up to ${options.maxFaults} faults a run, ${options.parallelism} at a time, ${ExploreOptions.shown(options.speed)}x the robot's clock"
        )
        val report = refusedAsFailure {
            StopSignals().use { signals ->
                runBlocking {
                    val interrupting = launch { signals.await(null)?.let { explorer.stop() } }
                    try {
                        explorer.explore(file, options, ::progress)
                    } finally {
                        interrupting.cancel()
                    }
                }
            }
        }
        status?.clear()
        summarise(report)
        junit?.let { echo("JUnit report: ${ExploreJUnit.write(report, it)}") }
        return report.failures.isNotEmpty()
    }

    /** Replays run [key] (`SEED:INDEX`) of [file] [reruns] times; whether its most common verdict is a failure. */
    fun replay(file: Path, key: String, maxFaults: Int, reruns: Int, parallelism: Int, speed: Double): Boolean {
        val (seed, index) = parseKey(key)
        val report = refusedAsFailure {
            runBlocking {
                FaultExplorer().replay(file, seed, index, maxFaults, reruns, parallelism, speed) { done, verdict ->
                    ran(done, reruns, key, verdict)
                }
            }
        }
        status?.clear()
        echo("run ${report.key} › ${report.scenario}: ${report.schedule}")
        report.failureLines.forEach { echo("  $it") }
        val percent = String.format(Locale.ROOT, "%.0f%%", report.agreement * 100)
        echo("replayed ${report.reruns} time(s) in ${seconds(report.elapsed)}: ${report.verdict}")
        echo("rerun agreement: ${report.agreeing} of ${report.reruns} ($percent) had that verdict")
        return report.failed
    }

    private fun ran(done: Int, reruns: Int, key: String, verdict: String) {
        if (status == null || reruns == 1) echo("run $key ($done of $reruns): $verdict")
        else status.show("$key: $done of $reruns reruns done")
    }

    private fun progress(run: ExploreProgress) {
        status?.clear()
        echo("run ${run.key} ${run.verdict.substringBefore('\n')} › ${run.scenario}: ${run.schedule}")
        status?.show(
            "${run.runs} runs, ${run.failed} failed (${run.distinct} distinct), ${run.skipped} skipped, ${oneDecimal(run.perMinute)} schedules/min"
        )
    }

    private fun summarise(report: ExploreReport) {
        if (report.interrupted) echo("stopped: what was found so far, unshrunk")
        for (found in report.failures) {
            echo("FAIL ${found.failure}")
            found.failure.details.forEach { echo("    $it") }
            echo(
                "  in ${found.occurrences} run(s) of scenario '${found.scenario}', first ${found.firstRun}: ${found.drawn}"
            )
            echo(
                "  smallest schedule (${found.faults} fault(s), ${found.shrinkRuns} shrinking runs): ${found.smallest}"
            )
            echo("  replay: ${found.replay}")
            found.test?.let { test ->
                val verified =
                    when (found.failsAsWritten) {
                        true -> "it fails as written"
                        false -> "it passed when run as written: the failure depends on timing"
                        null -> "not run"
                    }
                echo("  regression test: $test ($verified)")
            }
        }
        val skips = report.skipReasons.entries.joinToString("; ") { (why, count) -> "$count: $why" }
        val wall = report.elapsed.inWholeMilliseconds.coerceAtLeast(1).toDouble()
        // The robot's time the runs stood for, over the wall time: how much faster than the robot this explored.
        val speedUp = report.robotTime.inWholeMilliseconds / wall
        echo(
            "${report.runs} runs in ${seconds(report.elapsed)}: ${report.failed} failed (${report.failures.size} distinct), " +
                "${report.skipped} skipped${if (skips.isEmpty()) "" else " ($skips)"}; " +
                "${oneDecimal(report.runs * 60_000.0 / wall)} schedules/min, ${oneDecimal(speedUp)}x the robot's clock"
        )
    }

    private inline fun <T> refusedAsFailure(block: () -> T): T =
        try {
            block()
        } catch (e: ExploreRefused) {
            throw CommandFailed(e.lines.joinToString("; "))
        }

    companion object {
        /** `SEED:INDEX` as the two numbers. */
        fun parseKey(key: String): Pair<Long, Long> {
            val parts = key.split(':')
            val seed = parts.getOrNull(0)?.toLongOrNull()
            val index = parts.getOrNull(1)?.toLongOrNull()
            if (parts.size != 2 || seed == null || index == null || index < 0)
                throw CommandFailed("--replay $key: give SEED:INDEX, as a run's line shows it (e.g. 42:17)")
            return seed to index
        }

        private fun oneDecimal(value: Double): String = String.format(Locale.ROOT, "%.1f", value)

        private fun seconds(duration: Duration): String =
            String.format(Locale.ROOT, "%.1f s", duration.inWholeMilliseconds / 1000.0)
    }
}
