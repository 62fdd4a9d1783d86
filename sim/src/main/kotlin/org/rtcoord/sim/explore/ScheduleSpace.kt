package org.rtcoord.sim.explore

import java.util.SplittableRandom
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import org.rtcoord.sim.ManagerTopology
import org.rtcoord.sim.test.Fault
import org.rtcoord.sim.test.FaultKind
import org.rtcoord.sim.test.LoadedTest
import org.rtcoord.sim.test.ScenarioPlan
import org.rtcoord.sim.test.ScheduledFault
import org.rtcoord.sim.test.TestStep

/**
 * Every schedule an exploration of [test] may draw: up to [maxFaults] faults of the vocabulary, on the components and
 * managers of its system (as its `explore { }` narrows them), at moments within each scenario's window. [draw] is a
 * pure function of the seed and the index: the same pair gives the same schedule in any process, which is what
 * `--replay` relies on.
 */
internal class ScheduleSpace(val test: LoadedTest, val maxFaults: Int) {
    private val declared = test.searchSpace
    private val topology =
        ManagerTopology.of(test.profile, test.profile.components.map { it.instanceName }, emptyList())

    /** The managers by name, each with the components whose process it is. */
    private val hosts: Map<String, List<String>> = buildMap {
        topology.masterName?.let { put(it, topology.masterComponents) }
        topology.slaves.forEach { put(it.name, it.components) }
    }

    /** The scenarios explored. */
    val scenarios: List<ScenarioPlan> =
        declared.scenarios?.let { names -> test.scenarios.filter { it.name in names } } ?: test.scenarios

    val components: List<String> = declared.components ?: test.profile.components.map { it.instanceName }
    val managers: List<String> = declared.managers ?: hosts.keys.toList()

    /** Each fault that may be drawn. */
    val faults: List<Fault> =
        FaultKind.entries
            .flatMap { kind ->
                when (kind.on) {
                    FaultKind.On.COMPONENT -> components.map { Fault(kind, it) }
                    FaultKind.On.MANAGER -> managers.map { Fault(kind, it) }
                    FaultKind.On.SYSTEM -> listOf(Fault(kind, null))
                }
            }
            .filter { fault ->
                (declared.only.isEmpty() || declared.only.any { it.matches(fault) }) &&
                    declared.excluded.none { it.matches(fault) }
            }

    init {
        require(maxFaults >= 1) { "--max-faults must be at least 1" }
        val noScenario = declared.scenarios.orEmpty().filter { name -> test.scenarios.none { it.name == name } }
        require(noScenario.isEmpty()) {
            "explore { scenarios(...) }: no scenario ${noScenario.joinToString { "'$it'" }} in the test (scenarios: ${test.scenarios.joinToString { "'${it.name}'" }})"
        }
        val unknown = declared.managers.orEmpty().filter { it !in hosts && it.removeSuffix(".mgr") !in hosts }
        require(unknown.isEmpty()) {
            "explore { managers(...) }: no manager ${unknown.joinToString()} in the system (managers: ${hosts.keys.joinToString().ifEmpty { "none" }})"
        }
        require(faults.isNotEmpty()) {
            "explore { }: no fault is left to draw (components: ${components.joinToString().ifEmpty { "none" }}, managers: ${managers.joinToString().ifEmpty { "none" }})"
        }
    }

    /**
     * Components the test narrows the search to that the profile lacks: faults on them apply once the coordinator
     * created them.
     */
    val notInProfile: List<String> = components - test.profile.components.map { it.instanceName }.toSet()

    /**
     * The moments [scenario]'s faults are drawn at: the test's `window`, or from its start to the time its timeline
     * would take if each `at` came at its time and each expectation took its whole deadline, at most [LONGEST].
     */
    fun window(scenario: ScenarioPlan): ClosedRange<Duration> =
        declared.window
            ?: run {
                var end = Duration.ZERO
                for (step in scenario.steps) {
                    when (step) {
                        is TestStep.At -> end = maxOf(end, step.time)
                        is TestStep.Expect -> end += step.within
                        is TestStep.ExpectMode -> end += step.within
                        is TestStep.ExpectLog -> end += step.within
                        is TestStep.ExpectHandlerFailure -> end += step.within
                        else -> {}
                    }
                }
                Duration.ZERO..end.coerceIn(SHORTEST, LONGEST)
            }

    /**
     * Run [index] of [seed]: a scenario, one to [maxFaults] moments within its window (on a [GRAIN] grid), and at each
     * a fault that can still apply there (not on a component exited or killed with its manager earlier in the schedule,
     * a manager killed already, or a repair of what no earlier fault broke).
     */
    fun draw(seed: Long, index: Long): Schedule {
        val random = SplittableRandom(seed * SEED_STRIDE + index)
        val scenario = scenarios[random.nextInt(scenarios.size)]
        val window = window(scenario)
        val steps = (window.endInclusive - window.start).inWholeMilliseconds / GRAIN.inWholeMilliseconds
        val times =
            List(1 + random.nextInt(maxFaults)) { window.start + GRAIN * random.nextLong(steps + 1).toDouble() }
                .sorted()
        val gone = HashSet<String>()
        val breakable = HashSet<String>()
        val drawn = mutableListOf<ScheduledFault>()
        for (time in times) {
            val open = faults.filter { fault ->
                val target = fault.target
                when {
                    target != null && target in gone -> false
                    fault.kind == FaultKind.REPAIR -> target in breakable
                    else -> true
                }
            }
            if (open.isEmpty()) break
            val fault = open[random.nextInt(open.size)]
            drawn += ScheduledFault(time, fault)
            when {
                fault.kind == FaultKind.EXIT -> gone += fault.target!!
                fault.kind == FaultKind.KILL_MANAGER ->
                    gone += listOf(fault.target!!) + hosts[fault.target.removeSuffix(".mgr")].orEmpty()
                fault.kind.repairable -> breakable += fault.target!!
                fault.kind == FaultKind.REPAIR -> breakable -= fault.target!!
            }
        }
        return Schedule(seed, index, scenario, drawn)
    }

    private companion object {
        /** Seeds whose runs' random sequences do not overlap for any practical index. */
        const val SEED_STRIDE = -7046029254386353131L
        val GRAIN = 10.milliseconds
        val SHORTEST = 1.seconds
        val LONGEST = 10.seconds
    }
}
