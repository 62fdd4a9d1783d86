package org.rtcoord.sim.test

import java.nio.file.Path
import java.nio.file.Paths
import java.util.stream.Stream
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.async
import kotlinx.coroutines.cancel
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.sync.Semaphore
import kotlinx.coroutines.sync.withPermit
import org.junit.jupiter.api.DynamicContainer
import org.junit.jupiter.api.DynamicNode
import org.junit.jupiter.api.DynamicTest

/**
 * The JUnit 5 API: `*.test.kts` files as dynamic tests, a container per file and a test per scenario, each failing with
 * its `file:line:col: what` lines and what explains them. A file that cannot be run is one failing test. From Kotlin,
 * `@TestFactory fun coordinators() = CoordinatorTests.of("examples")`; from Java, `@TestFactory Stream<DynamicNode>
 * coordinators() { return CoordinatorTests.of("examples"); }`.
 */
public object CoordinatorTests {
    /** A container per `*.test.kts` file of [paths] (files, or directories whose test files are taken). */
    @JvmStatic public fun of(vararg paths: String): Stream<DynamicNode> = of(paths.map { Paths.get(it) })

    /** A container per `*.test.kts` file of [paths]; each file is loaded when JUnit comes to it. */
    @JvmStatic
    public fun of(paths: List<Path>): Stream<DynamicNode> {
        val runner = CoordinatorTestRunner(parallelism = 1)
        return runner.files(paths).stream().map { file ->
            DynamicContainer.dynamicContainer(
                file.name,
                file.path.toUri(),
                Stream.of(file).flatMap { scenarios(runner, it) },
            )
        }
    }

    /**
     * As [of], with [parallelism] scenarios running at a time: every file is loaded and its scenarios started at once,
     * and each test waits for its own. A scenario mostly waits on the robot's clock, so several at a time take a
     * fraction of the time one after another does, at a little more CPU. Closing the stream (JUnit does, once it ran
     * them) stops what still runs.
     */
    @JvmStatic
    public fun of(parallelism: Int, vararg paths: String): Stream<DynamicNode> {
        require(parallelism >= 1) { "parallelism must be at least 1, was $parallelism" }
        val runner = CoordinatorTestRunner(parallelism = parallelism)
        val scope = CoroutineScope(SupervisorJob() + Dispatchers.IO)
        val permits = Semaphore(parallelism)
        val started =
            runner.files(paths.map { Paths.get(it) }).map { file ->
                file to
                    scope.async {
                        when (val loaded = permits.withPermit { runner.load(file) }) {
                            is CoordinatorTestRunner.Loaded.Failed ->
                                listOf(file.name to CompletableDeferred(loaded.result))
                            is CoordinatorTestRunner.Loaded.Runnable ->
                                loaded.test.scenarios.map { scenario ->
                                    scenario.name to scope.async { permits.withPermit { runner.run(scenario) } }
                                }
                        }
                    }
            }
        return started
            .stream()
            .map<DynamicNode> { (file, scenarios) ->
                DynamicContainer.dynamicContainer(
                    file.name,
                    file.path.toUri(),
                    Stream.of(file).flatMap {
                        runBlocking { scenarios.await() }
                            .stream()
                            .map { (name, result) -> test(name, file) { runBlocking { result.await() } } }
                    },
                )
            }
            .onClose { scope.cancel() }
    }

    private fun scenarios(runner: CoordinatorTestRunner, file: TestFile): Stream<DynamicNode> =
        when (val loaded = runBlocking { runner.load(file) }) {
            is CoordinatorTestRunner.Loaded.Failed -> Stream.of(test(file.name, file) { loaded.result })
            is CoordinatorTestRunner.Loaded.Runnable ->
                loaded.test.scenarios.stream().map { scenario ->
                    test(scenario.name, file) { runBlocking { runner.run(scenario) } }
                }
        }

    private fun test(name: String, file: TestFile, result: () -> TestResult): DynamicNode =
        DynamicTest.dynamicTest(name, file.path.toUri()) {
            val outcome = result()
            if (!outcome.passed)
                throw AssertionError((TestReport.failures(outcome) + TestReport.timeline(outcome)).joinToString("\n"))
        }
}
