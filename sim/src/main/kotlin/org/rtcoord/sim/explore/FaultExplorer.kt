package org.rtcoord.sim.explore

import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration
import kotlin.time.TimeSource
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.test.Injection
import org.rtcoord.sim.test.LoadedTest
import org.rtcoord.sim.test.ScenarioPlan
import org.rtcoord.sim.test.ScenarioRun
import org.rtcoord.sim.test.TestFiles
import org.rtcoord.sim.test.TestLoader
import org.rtcoord.sim.test.TestReport
import org.rtcoord.sim.test.TestResult
import org.rtcoord.sim.test.TestScriptHost
import org.rtcoord.sim.test.TestStep
import org.rtcoord.sim.test.UnrunnableTest

/**
 * `rtcoord test --explore`: searches the fault schedules a test's system can meet for the ones that make its
 * coordinator fail. Each run draws a schedule from the seed and its index ([ScheduleSpace]), plays the test's scenario
 * on a fresh simulated system with the schedule's faults applied alongside its steps, and judges it by the test's
 * oracle: its invariants, its expectations, a handler that fails. A fault that cannot be applied skips the run. Each
 * distinct failure (by where it fails) is shrunk to the smallest schedule that still fails there ([ScheduleShrinker])
 * and written as a regression test ([FoundTest]).
 *
 * Refused ([ExploreRefused]): a test that cannot be loaded, one with nothing to check (no invariant and no
 * expectation), and one that fails without any fault. [stop] (Ctrl-C) ends an exploration early with what it found so
 * far, unshrunk.
 */
public class FaultExplorer @JvmOverloads constructor(private val scripts: ScriptHost = ScriptHost()) {
    private val loader = TestLoader(TestScriptHost(), scripts)
    private val stopping = CompletableDeferred<Unit>()

    /** Ends the exploration under way (or the next) early: runs in flight are abandoned, what was found is reported. */
    public fun stop() {
        stopping.complete(Unit)
    }

    /**
     * Explores the test at [path] as [options] say, telling [progress] of each run as it ends (from any thread, one at
     * a time). Throws [ExploreRefused] for a test that cannot be explored.
     */
    public suspend fun explore(
        path: Path,
        options: ExploreOptions,
        progress: (ExploreProgress) -> Unit = {},
    ): ExploreReport = coroutineScope {
        val began = TimeSource.Monotonic.markNow()
        val test = load(path)
        val space = space(test, options.maxFaults)
        baseline(space.scenarios, options.parallelism, options.speed)
        val found = Findings()
        val deadline = options.duration?.let { began + it }
        val workers = launch {
            staggeredRuns(options.parallelism, options.runLimit, { deadline?.hasPassedNow() != true }) { index ->
                val schedule = space.draw(options.seed, index)
                val result = run(schedule, options.speed)
                synchronized(found) { progress(found.add(schedule, result, began.elapsedNow())) }
            }
        }
        val interrupting = launch {
            stopping.await()
            workers.cancel()
        }
        workers.join()
        interrupting.cancel()
        val interrupted = stopping.isCompleted
        val failures =
            found.groups.values.map { group ->
                val replay = replayCommand(test, group.schedule, options)
                if (interrupted) return@map group.found(group.schedule, 0, replay, null, null)
                val shrinker =
                    ScheduleShrinker(options.shrinkRuns) { candidate ->
                        val verdict = Verdict.of(run(candidate, options.speed))
                        verdict is Verdict.Failed && verdict.key == group.verdict.key
                    }
                val smallest = shrinker.shrink(group.schedule)
                val written =
                    if (options.writeTests)
                        FoundTest.write(test, group.schedule, smallest, group.verdict.failure, replay)
                    else null
                group.found(smallest, shrinker.runs, replay, written, written?.let { failsAsWritten(it) })
            }
        ExploreReport(
            test.file,
            options.seed,
            found.runs,
            found.failed,
            found.skipped,
            found.skipReasons.toMap(),
            began.elapsedNow(),
            found.robotTime,
            interrupted,
            failures,
        )
    }

    /**
     * Runs schedule [index] of [seed] (drawn with at most [maxFaults] faults, as the exploration that found it drew it)
     * of the test at [path] [reruns] times, [parallelism] at once, telling [progress] of each run's verdict; the report
     * says how many agree.
     */
    public suspend fun replay(
        path: Path,
        seed: Long,
        index: Long,
        maxFaults: Int,
        reruns: Int,
        parallelism: Int = 1,
        speed: Double = ExploreOptions.DEFAULT_SPEED,
        progress: (Int, String) -> Unit = { _, _ -> },
    ): ReplayReport = coroutineScope {
        require(reruns >= 1) { "--reruns must be at least 1" }
        val began = TimeSource.Monotonic.markNow()
        val test = load(path)
        val schedule = space(test, maxFaults).draw(seed, index)
        val done = AtomicLong()
        val rerun = arrayOfNulls<TestResult>(reruns)
        staggeredRuns(parallelism, reruns.toLong()) { rerunIndex ->
            val result = run(schedule, speed)
            rerun[rerunIndex.toInt()] = result
            progress(done.incrementAndGet().toInt(), Verdict.of(result).toString())
        }
        val results = rerun.map { checkNotNull(it) }
        val verdicts = results.map(Verdict::of)
        val common = verdicts.maxBy { v -> verdicts.count { it.agrees(v) } }
        val firstFailed = results.firstOrNull { !it.passed }
        ReplayReport(
            schedule.key,
            schedule.scenario.name,
            schedule.toString(),
            reruns,
            verdicts.map(Verdict::toString),
            common.toString(),
            verdicts.count { it.agrees(common) },
            firstFailed?.let { TestReport.failures(it) + TestReport.timeline(it) }.orEmpty(),
            began.elapsedNow(),
        )
    }

    private suspend fun load(path: Path): LoadedTest {
        val file =
            try {
                TestFiles.find(listOf(path)).singleOrNull()
                    ?: throw ExploreRefused(listOf("$path: explore one test file at a time"))
            } catch (e: IllegalArgumentException) {
                throw ExploreRefused(listOf(e.message.orEmpty()))
            }
        if (Files.isDirectory(path)) throw ExploreRefused(listOf("$path: explore one test file at a time"))
        val test =
            try {
                withContext(Dispatchers.IO) { loader.load(file) }
            } catch (e: UnrunnableTest) {
                throw ExploreRefused(e.failures.map { it.toString() })
            }
        val checks = test.scenarios.flatMap { it.steps }.filter { it !is TestStep.At && it !is TestStep.Meanwhile }
        if (checks.isEmpty()) {
            throw ExploreRefused(
                listOf(
                    "${file.path}: nothing to check: the test has no invariant (always, never) and no expectation, so no schedule could fail it"
                )
            )
        }
        return test
    }

    private fun space(test: LoadedTest, maxFaults: Int): ScheduleSpace =
        try {
            ScheduleSpace(test, maxFaults)
        } catch (e: IllegalArgumentException) {
            throw ExploreRefused(listOf("${test.file.path}: ${e.message}"))
        }

    /** Runs each of [scenarios] once without faults: one that fails so is refused, as every schedule would fail it. */
    private suspend fun baseline(scenarios: List<ScenarioPlan>, parallelism: Int, speed: Double) {
        val results = arrayOfNulls<TestResult>(scenarios.size)
        staggeredRuns(parallelism, scenarios.size.toLong()) { index ->
            results[index.toInt()] = runPlain(scenarios[index.toInt()], speed)
        }
        val failed = results.map { checkNotNull(it) }.filterNot { it.passed }
        if (failed.isNotEmpty()) {
            throw ExploreRefused(
                failed.flatMap { result ->
                    listOf("${result.name} fails without any fault injected; fix it (or the test) first:") +
                        TestReport.failures(result).map { "  $it" }
                }
            )
        }
    }

    private suspend fun runPlain(scenario: ScenarioPlan, speed: Double): TestResult =
        ScenarioRun(scenario, scripts, speed = speed).run()

    private suspend fun run(schedule: Schedule, speed: Double): TestResult =
        withContext(Dispatchers.IO) {
            ScenarioRun(schedule.scenario, scripts, schedule.faults.map(Injection::of), speed = speed).run()
        }

    /**
     * Whether the regression test at [path] fails when run as written (one that cannot even be loaded does not count).
     */
    private suspend fun failsAsWritten(path: Path): Boolean =
        try {
            val test = withContext(Dispatchers.IO) { loader.load(TestFiles.find(listOf(path)).single()) }
            test.scenarios.any { !runPlain(it, 1.0).passed }
        } catch (e: CancellationException) {
            throw e
        } catch (e: Exception) {
            false
        }

    private fun replayCommand(test: LoadedTest, schedule: Schedule, options: ExploreOptions): String =
        "rtcoord test --explore --replay ${schedule.key}" +
            (if (options.maxFaults != ExploreOptions.DEFAULT_MAX_FAULTS) " --max-faults ${options.maxFaults}" else "") +
            (if (options.speed != ExploreOptions.DEFAULT_SPEED) " --speed ${ExploreOptions.shown(options.speed)}"
            else "") +
            " ${test.file.path}"

    /** The runs' verdicts so far, the failures grouped by where they fail; guarded by its own lock. */
    private class Findings {
        var runs = 0
        var failed = 0
        var skipped = 0
        var robotTime = Duration.ZERO
        val skipReasons = LinkedHashMap<String, Int>()
        val groups = LinkedHashMap<String, Group>()

        fun add(schedule: Schedule, result: TestResult, elapsed: Duration): ExploreProgress {
            runs++
            robotTime += result.timeline.lastOrNull()?.at?.coerceAtLeast(Duration.ZERO) ?: Duration.ZERO
            when (val verdict = Verdict.of(result)) {
                is Verdict.Failed -> {
                    failed++
                    groups.getOrPut(verdict.key) { Group(verdict, schedule) }.occurrences++
                }
                is Verdict.Skipped -> {
                    skipped++
                    val reason = verdict.why.substringAfter("cannot be applied: ").substringBefore(" (")
                    skipReasons.merge(reason, 1, Int::plus)
                }
                Verdict.Passed -> {}
            }
            return ExploreProgress(
                schedule.key,
                schedule.scenario.name,
                schedule.toString(),
                Verdict.of(result).toString(),
                runs,
                failed,
                skipped,
                groups.size,
                elapsed,
            )
        }
    }

    /** The first run that failed at one place, and how many did. */
    private class Group(val verdict: Verdict.Failed, val schedule: Schedule) {
        var occurrences = 0

        fun found(smallest: Schedule, shrinkRuns: Int, replay: String, test: Path?, failsAsWritten: Boolean?) =
            FoundFailure(
                verdict.failure,
                schedule.scenario.name,
                occurrences,
                schedule.key,
                schedule.toString(),
                smallest.toString(),
                smallest.faults.size,
                shrinkRuns,
                replay,
                test,
                failsAsWritten,
                verdict.result.timeline,
            )
    }
}
