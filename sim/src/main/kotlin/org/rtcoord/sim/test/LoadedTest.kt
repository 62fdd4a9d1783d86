package org.rtcoord.sim.test

import java.nio.file.Path
import org.rtcoord.profile.RtsProfile

/**
 * A test file loaded and found runnable: the [profile] of its system, its coordinator script, and its scenarios, each
 * the steps written at the top of the file followed by its own.
 */
internal class LoadedTest(
    val file: TestFile,
    val source: TestSource,
    val profile: RtsProfile,
    /** The system's profile file, as messages show it. */
    val systemShown: Path,
    /** Where the test names its system: `file:line:col`. */
    val systemAt: String,
    val coordinator: Path,
    /** The coordinator script, as messages show it. */
    val coordinatorShown: Path,
    /** Where the test names its coordinator: `file:line:col`. */
    val coordinatorAt: String,
    val args: List<String>,
    declared: CoordinatorTest,
) {
    /** The directories of the IDL files for the system's own data types. */
    val idlDirectories: List<Path> = declared.idlDirectories.map { it.path }

    /** What `--explore` searches, as the test's `explore { }` narrows it. */
    val searchSpace: SearchSpace = declared.searchSpace

    /** The lines the file's scenarios are declared on, in order. */
    val scenarioLines: List<Int> = declared.scenarios.map { it.declaredAt }

    /** The scenarios, in the order declared; the file itself as one when it declares none. */
    val scenarios: List<ScenarioPlan> =
        if (declared.scenarios.isEmpty()) listOf(ScenarioPlan(this, file.name, declared.steps.toList(), null))
        else declared.scenarios.map { ScenarioPlan(this, it.name, declared.steps + it.steps, it.declaredAt) }
}

/**
 * One scenario of a [test]: its [name] and its [steps], those at the top of the file first, and the line it is
 * [declared at][declaredAt] (null for a file without scenarios).
 */
internal class ScenarioPlan(val test: LoadedTest, val name: String, val steps: List<TestStep>, val declaredAt: Int?) {
    /** The texts of the handler failures it expects: a handler failure with none of them fails it. */
    val expectedHandlerFailures: List<String> = steps.filterIsInstance<TestStep.ExpectHandlerFailure>().map { it.text }

    /** The faults of its `meanwhile` blocks, applied alongside its steps. */
    val injections: List<Injection> =
        steps
            .filterIsInstance<TestStep.Meanwhile>()
            .flatMap { it.faults }
            .map { at -> Injection(at.time, test.source.at(at), at.faults) }
}
