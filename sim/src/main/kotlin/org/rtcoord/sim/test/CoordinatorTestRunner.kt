package org.rtcoord.sim.test

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.sync.Semaphore
import kotlinx.coroutines.sync.withPermit
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeout
import org.rtcoord.ComponentNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.sim.SimulatedSystem
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.io.path.name
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource

/**
 * Runs `*.test.kts` files, each against a fresh [SimulatedSystem] built from the profile it names, with
 * its coordinator compiled by the dsl's [ScriptHost], [parallelism] at a time. Test scripts are kept
 * compiled in [ScriptHost.defaultCacheDirectory], as coordinators are: an unchanged one starts at once.
 */
public class CoordinatorTestRunner @JvmOverloads constructor(
    private val parallelism: Int = Runtime.getRuntime().availableProcessors(),
    private val scripts: ScriptHost = ScriptHost(),
) {
    private val tests = TestScriptHost()

    /** The test files [paths] name: each file as given, each directory's `*.test.kts` files, sorted. */
    public fun files(paths: List<Path>): List<Path> = paths.flatMap { path ->
        require(Files.exists(path)) { "$path: no such file or directory" }
        if (Files.isDirectory(path)) Files.list(path).use { list -> list.filter { it.name.endsWith(".test.kts") }.sorted().toList() } else listOf(path)
    }

    /** Runs every file of [files], in parallel where allowed; results in the order of [files]. */
    public suspend fun runAll(files: List<Path>): List<TestResult> = coroutineScope {
        val permits = Semaphore(parallelism.coerceAtLeast(1))
        files.map { file -> async { permits.withPermit { run(file) } } }.awaitAll()
    }

    /** Runs one test file. */
    public suspend fun run(file: Path): TestResult = withContext(Dispatchers.IO) {
        val started = TimeSource.Monotonic.markNow()
        val log = CopyOnWriteArrayList<String>()
        val failures = try {
            execute(file, tests.load(file), log)
        } catch (e: ScriptFailure) {
            e.problems
        }
        TestResult(file, failures, started.elapsedNow(), log.toList())
    }

    private suspend fun execute(file: Path, test: CoordinatorTest, log: MutableList<String>): List<String> {
        val systemFile = test.systemFile ?: return listOf("$file:1: the test names no system: system(\"SYSTEM.xml\")")
        val coordinatorFile = test.coordinatorFile ?: return listOf("$file:1: the test names no coordinator: coordinator(\"NAME.coord.kts\")")
        val system = try {
            SimulatedSystem.start(systemFile, idlDirectories = test.idlDirectories)
        } catch (e: Exception) {
            return listOf("$file:1: cannot simulate $systemFile: ${e.message}")
        }
        return system.use {
            val host = TreeConfig(listOf(system.address))
            RtcTree.create(host).use { tree ->
                val coordination = scripts.load(coordinatorFile, test.coordinatorArgs, host)
                Coordinator(tree, coordination, null) { log += it }.use { coordinator ->
                    withTimeout(START_DEADLINE) { coordinator.start() }
                    timeline(file, test, system, tree, coordinator, log)
                }
            }
        }
    }

    private suspend fun timeline(
        file: Path,
        test: CoordinatorTest,
        system: SimulatedSystem,
        tree: RtcTree,
        coordinator: Coordinator,
        log: List<String>,
    ): List<String> {
        val failures = mutableListOf<String>()
        val start = TimeSource.Monotonic.markNow()
        val expectation = object : Expectation {
            override suspend fun component(name: String): ComponentNode {
                val instance = name.removeSuffix(".rtc")
                val component = system.component(instance)
                return tree.component("/${system.address}/${(component.contexts + "$instance.rtc").joinToString("/")}")
            }

            override fun modeOf(machine: String): String? = coordinator.machine(machine).mode.value

            override val log: List<String> get() = log.toList()
        }
        for (step in test.steps) {
            when (step) {
                is TestStep.At -> {
                    delay(step.time - start.elapsedNow())
                    try {
                        step.scenario(SimScenario(system))
                    } catch (e: Exception) {
                        failures += "$file:${step.line}: at ${step.time}: ${e.message}"
                    }
                }
                is TestStep.Expect -> expect(step, expectation)?.let { failures += "$file:${step.line}: $it" }
            }
        }
        // Counted by the supervisors themselves: every restart, however close together.
        val restarts = coordinator.supervision.flatMap { it.status.value.restartsByChild.entries }
        for ((component, line) in test.noRestarts) {
            val times = restarts.filter { it.key.substringAfterLast('/').removeSuffix(".rtc") == component }.sumOf { it.value }
            if (times > 0) failures += "$file:$line: expected no restarts of $component, but a supervisor restarted it $times time(s)"
        }
        return failures
    }

    /** Null when [step]'s condition holds within its deadline, else what was expected and what was seen last. */
    private suspend fun expect(step: TestStep.Expect, expectation: Expectation): String? {
        val deadline = TimeSource.Monotonic.markNow() + step.within
        var last: String? = null
        while (true) {
            val held = try {
                step.condition(expectation)
            } catch (e: Exception) {
                last = e.message ?: e.javaClass.simpleName
                false
            }
            if (held) return null
            if (deadline.hasPassedNow()) return "expected ${step.what} within ${step.within}, but it did not hold${last?.let { " ($it)" } ?: ""}"
            delay(POLL)
        }
    }

    private companion object {
        val START_DEADLINE = 30.seconds
        val POLL = 20.milliseconds
    }
}
