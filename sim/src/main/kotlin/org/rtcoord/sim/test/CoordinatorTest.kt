package org.rtcoord.sim.test

import org.rtcoord.ComponentNode
import java.nio.file.Path
import java.nio.file.Paths
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * What a `NAME.test.kts` says: the [system] to simulate, the [coordinator] to run on it, and a timeline
 * of scenario steps ([at]) and expectations ([expect], [expectMode], [expectLog]), taken in the order
 * written, plus [expectNoRestartsOf], checked when the timeline ends. Each step remembers the line of the
 * test file it was written on, which its failure names. File names are relative to [directory].
 */
public abstract class CoordinatorTest(
    /** The test file's directory. */
    public val directory: Path = Paths.get(""),
    /** The test file's name. */
    public val name: String = "unnamed.test.kts",
) {
    internal var systemFile: Path? = null
    internal var coordinatorFile: Path? = null
    internal var coordinatorArgs: List<String> = emptyList()
    internal val steps = mutableListOf<TestStep>()
    internal val noRestarts = mutableListOf<Pair<String, Int>>()

    /** Simulates the system the RTSProfile [profile] describes (`rtcoord profile save` writes one). */
    public fun system(profile: String) {
        systemFile = directory.resolve(profile)
    }

    /** Runs the coordinator script [script] with [args] against the simulated system. */
    public fun coordinator(script: String, vararg args: String) {
        coordinatorFile = directory.resolve(script)
        coordinatorArgs = args.toList()
    }

    /** At [time] after the coordinator started (at once if that is past), does what [scenario] says to the system. */
    public fun at(time: Duration, scenario: Scenario.() -> Unit) {
        steps += TestStep.At(line(), time, scenario)
    }

    /** Expects [condition] to hold within [within] from here in the timeline; polled until it does. */
    public fun expect(within: Duration = DEFAULT_WITHIN, condition: suspend Expectation.() -> Boolean) {
        steps += TestStep.Expect(line(), within, "the condition", condition)
    }

    /**
     * Expects the coordinator's mode machine [machine] to be in [mode] within [within]: a path below the
     * machine (`degraded/odometry`) or one mode's name (`odometry`); a machine in a nested mode is in
     * each mode that contains it.
     */
    public fun expectMode(machine: String, mode: String, within: Duration = DEFAULT_WITHIN) {
        steps += TestStep.Expect(line(), within, "mode machine $machine in mode $mode") {
            val active = modeOf(machine)?.removePrefix("$machine/")
            active != null && (active == mode || active.startsWith("$mode/") || ('/' !in mode && mode in active.split('/')))
        }
    }

    /** Expects the coordinator to log a line containing [text] within [within]. */
    public fun expectLog(text: String, within: Duration = DEFAULT_WITHIN) {
        steps += TestStep.Expect(line(), within, "a log line containing '$text'") { log.any { text in it } }
    }

    /** Expects no supervisor of the coordinator to restart [component] (`laser0` or `laser0.rtc`) during the test. */
    public fun expectNoRestartsOf(component: String) {
        noRestarts += component.removeSuffix(".rtc") to line()
    }

    /** The line of the test file the calling step is written on. */
    private fun line(): Int = Throwable().stackTrace.firstOrNull { it.fileName == name }?.lineNumber ?: 0

    private companion object {
        val DEFAULT_WITHIN = 5.seconds
    }
}

/** One step of a test's timeline, with the line of the test file it was written on. */
internal sealed class TestStep(val line: Int) {
    class At(line: Int, val time: Duration, val scenario: Scenario.() -> Unit) : TestStep(line)

    class Expect(line: Int, val within: Duration, val what: String, val condition: suspend Expectation.() -> Boolean) : TestStep(line)
}

/** What an expectation can look at: the simulated system's components and the coordinator's modes and log. */
public interface Expectation {
    /** The component [name] (`odo_localise0` or `odo_localise0.rtc`) in the simulated system; throws when it does not exist (yet). */
    public suspend fun component(name: String): ComponentNode

    /** The active mode of the coordinator's mode machine [machine], or null before it has one. */
    public fun modeOf(machine: String): String?

    /** The coordinator's log, one line a message, so far. */
    public val log: List<String>
}

/** The faults and actions a scenario step applies to the simulated system, by component name. */
public interface Scenario {
    /** The component breaks: it goes to ERROR and every reset fails until [repair]. */
    public fun breakDown(component: String)

    /** The component's next execution fails: it goes to ERROR; a reset recovers it. */
    public fun fail(component: String)

    /** Ends [breakDown], [hang] and [freeze]. */
    public fun repair(component: String)

    /** Its out-ports stop publishing while it stays ACTIVE. */
    public fun freeze(component: String)

    /** Its `on_execute` never returns, stalling its execution context. */
    public fun hang(component: String)

    /** The component exits, as rtexit does. */
    public fun exit(component: String)

    /** The master manager's process dies, with the components it hosts itself. */
    public fun killManager()

    /**
     * The process of manager [name] dies with every component it hosts: a slave (`localisation`, or
     * `manager.mgr/localisation`) or the master (`manager.mgr`), as the profile saved them.
     */
    public fun killManager(name: String)

    /** The naming service restarts with its bindings. */
    public fun restartNaming()
}
