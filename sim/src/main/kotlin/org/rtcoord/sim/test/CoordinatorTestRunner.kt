package org.rtcoord.sim.test

import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.TimeSource
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.sync.Semaphore
import kotlinx.coroutines.sync.withPermit
import kotlinx.coroutines.withContext
import org.rtcoord.dsl.script.ScriptHost

/**
 * Runs `*.test.kts` files: each scenario against a fresh simulated system built from the profile its file names, with
 * the file's coordinator compiled by the dsl's [ScriptHost], [parallelism] scenarios at a time. Test scripts are kept
 * compiled in [ScriptHost.defaultCacheDirectory], as coordinators are: an unchanged one starts at once. Whatever a test
 * does (it does not compile, its coordinator names what the system lacks, a scenario cannot be run at all), it is a
 * failed result and every other test still runs. Scenarios run [speed] times as fast as the robot's clock
 * (`TreeConfig.speed`).
 */
public class CoordinatorTestRunner
@JvmOverloads
constructor(
    private val parallelism: Int = Runtime.getRuntime().availableProcessors(),
    private val scripts: ScriptHost = ScriptHost(),
    private val speed: Double = 1.0,
) {
    private val loader = TestLoader(TestScriptHost(), scripts)

    init {
        require(speed > 0 && speed.isFinite()) { "speed must be positive, was $speed" }
    }

    /**
     * How long a handler may run before the coordinator is said to have stopped reacting: shorter in the tests of that
     * verdict.
     */
    internal var stuckAfter: Duration = ScenarioRun.STUCK

    /**
     * The test files [paths] name, each with a name unique in the run: each file as given, each directory's
     * `*.test.kts` files at any depth, sorted, named by their paths relative to it. Throws [IllegalArgumentException]
     * for a path that does not exist.
     */
    public fun files(paths: List<Path>): List<TestFile> = TestFiles.find(paths)

    /**
     * Runs every scenario of every file of [files], [parallelism] at a time; results in the order of [files], then of
     * scenarios.
     */
    public suspend fun runAll(files: List<TestFile>): List<TestResult> = coroutineScope {
        val permits = Semaphore(parallelism.coerceAtLeast(1))
        files
            .map { file ->
                async {
                    when (val loaded = permits.withPermit { load(file) }) {
                        is Loaded.Runnable ->
                            loaded.test.scenarios
                                .map { scenario -> async { permits.withPermit { run(scenario) } } }
                                .awaitAll()
                        is Loaded.Failed -> listOf(loaded.result)
                    }
                }
            }
            .awaitAll()
            .flatten()
    }

    /** Runs every scenario of [file], one after another. */
    public suspend fun run(file: TestFile): List<TestResult> =
        when (val loaded = load(file)) {
            is Loaded.Runnable -> loaded.test.scenarios.map { run(it) }
            is Loaded.Failed -> listOf(loaded.result)
        }

    /** A test file loaded: runnable, or failed with why. */
    internal sealed class Loaded {
        class Runnable(val test: LoadedTest) : Loaded()

        class Failed(val result: TestResult) : Loaded()
    }

    /** Loads [file], never throwing for what it holds. */
    internal suspend fun load(file: TestFile): Loaded =
        withContext(Dispatchers.IO) {
            val began = TimeSource.Monotonic.markNow()
            fun failed(failures: List<TestFailure>) =
                Loaded.Failed(TestResult(file, file.name, failures, began.elapsedNow(), emptyList(), emptyList()))
            try {
                Loaded.Runnable(loader.load(file))
            } catch (e: UnrunnableTest) {
                failed(e.failures)
            } catch (e: CancellationException) {
                throw e
            } catch (e: Exception) {
                failed(
                    listOf(
                        TestFailure(
                            "${file.path}:1:1",
                            "the test could not be loaded: ${e.javaClass.simpleName}: ${e.message}",
                        )
                    )
                )
            }
        }

    /** Runs [scenario] on a system of its own. */
    internal suspend fun run(scenario: ScenarioPlan): TestResult =
        withContext(Dispatchers.IO) { ScenarioRun(scenario, scripts, stuckAfter = stuckAfter, speed = speed).run() }
}
