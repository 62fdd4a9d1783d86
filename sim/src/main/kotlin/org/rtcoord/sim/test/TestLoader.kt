@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.sim.test

import java.nio.file.Files
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordination
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.dsl.script.ScriptSource
import org.rtcoord.profile.ProfileFormatException
import org.rtcoord.profile.RtsProfiles

/**
 * Loads a test file and checks, before anything runs, what can be checked: that it compiles and runs, names a system
 * and a coordinator whose files are there, a profile that reads and a coordinator that compiles, scenarios with names
 * of their own, and modes its coordinator declares. Each problem is a [TestFailure] at the line that has it;
 * [UnrunnableTest] carries them all.
 */
internal class TestLoader(private val tests: TestScriptHost, private val scripts: ScriptHost) {
    suspend fun load(file: TestFile): LoadedTest {
        val declared =
            try {
                tests.load(file.path)
            } catch (e: ScriptFailure) {
                throw UnrunnableTest(e.problems.map(TestFailure::of))
            }
        val source = TestSource(file.path, ScriptSource(Files.readString(file.path)))
        val system =
            declared.system
                ?: throw UnrunnableTest(
                    listOf(TestFailure("${file.path}:1:1", "the test names no system: write system(\"SYSTEM.xml\")"))
                )
        val coordinator =
            declared.coordinator
                ?: throw UnrunnableTest(
                    listOf(
                        TestFailure(
                            "${file.path}:1:1",
                            "the test names no coordinator: write coordinator(\"NAME.coord.kts\")",
                        )
                    )
                )
        val systemAt = source.at(system.line, "system")
        val coordinatorAt = source.at(coordinator.line, "coordinator")
        val problems = mutableListOf<TestFailure>()
        if (!Files.isRegularFile(system.path))
            problems += TestFailure(systemAt, "no such system file: ${TestFiles.shown(system.path)}")
        if (!Files.isRegularFile(coordinator.path))
            problems += TestFailure(coordinatorAt, "no such coordinator file: ${TestFiles.shown(coordinator.path)}")
        for (idl in declared.idlDirectories.filterNot { Files.isDirectory(it.path) }) {
            problems += TestFailure(source.at(idl.line, "idl"), "no such IDL directory: ${TestFiles.shown(idl.path)}")
        }
        if (problems.isNotEmpty()) throw UnrunnableTest(problems)
        val profile =
            try {
                RtsProfiles.read(system.path)
            } catch (e: ProfileFormatException) {
                throw UnrunnableTest(
                    listOf(
                        TestFailure(
                            if (e.line > 0) "${TestFiles.shown(system.path)}:${e.line}" else systemAt,
                            "cannot read the system ${TestFiles.shown(system.path)}: ${e.reason}",
                        )
                    )
                )
            }
        val coordinatorShown = TestFiles.shown(coordinator.path)
        val coordination =
            try {
                scripts.load(coordinatorShown, declared.coordinatorArgs, TreeConfig())
            } catch (e: ScriptFailure) {
                throw UnrunnableTest(e.problems.map(TestFailure::of))
            }
        problems += scenarioNames(declared, source) + modes(declared, coordination, source)
        if (problems.isNotEmpty()) throw UnrunnableTest(problems)
        return LoadedTest(
            file,
            source,
            profile,
            TestFiles.shown(system.path),
            systemAt,
            coordinator.path,
            coordinatorShown,
            coordinatorAt,
            declared.coordinatorArgs,
            declared,
        )
    }

    private fun scenarioNames(declared: CoordinatorTest, source: TestSource): List<TestFailure> {
        val seen = HashSet<String>()
        return declared.scenarios.mapNotNull { scenario ->
            when {
                scenario.name.isBlank() ->
                    TestFailure(source.at(scenario.declaredAt, "scenario"), "a scenario needs a name")
                !seen.add(scenario.name) ->
                    TestFailure(
                        source.at(scenario.declaredAt, "scenario"),
                        "a second scenario named '${scenario.name}'",
                    )
                else -> null
            }
        }
    }

    /** Each `expectMode` whose machine or mode the coordinator does not declare. */
    private fun modes(declared: CoordinatorTest, coordination: Coordination, source: TestSource): List<TestFailure> {
        val steps = (declared.steps + declared.scenarios.flatMap { it.steps }).filterIsInstance<TestStep.ExpectMode>()
        return steps.mapNotNull { step ->
            val machine =
                coordination.machines.firstOrNull { it.name == step.machine }
                    ?: return@mapNotNull TestFailure(
                        source.at(step),
                        "no such mode machine '${step.machine}' in the coordinator (machines: ${coordination.machines.joinToString { it.name }.ifEmpty { "none" }})",
                    )
            val paths = machine.modes.map { it.path.removePrefix("${machine.name}/") }
            val known = step.mode in paths || ('/' !in step.mode && machine.modes.any { it.name == step.mode })
            if (known) null
            else
                TestFailure(
                    source.at(step),
                    "no such mode '${step.mode}' in mode machine ${machine.name} (modes: ${paths.joinToString()})",
                )
        }
    }
}

/** A test file that cannot be run, and why: each problem where it is. */
internal class UnrunnableTest(val failures: List<TestFailure>) : Exception(failures.joinToString("\n"))
