package org.rtcoord.sim.test

import java.nio.file.Path
import java.nio.file.Paths

/**
 * What a `NAME.test.kts` says: the [system] to simulate, the [coordinator] to run on it, and its [scenario]s, each run
 * on a fresh system with the coordinator started anew. Steps and invariants written at the top (see [Timeline]) start
 * every scenario; a file without scenarios is one scenario, named after the file. File names are relative to
 * [directory].
 */
public abstract class CoordinatorTest(
    /** The test file's directory. */
    public val directory: Path = Paths.get(""),
    /** The test file's name. */
    public val name: String = "unnamed.test.kts",
) : Timeline(name) {
    internal var system: Declared? = null
    internal var coordinator: Declared? = null
    internal var coordinatorArgs: List<String> = emptyList()
    internal val idlDirectories = mutableListOf<Declared>()
    internal val scenarios = mutableListOf<Scenario>()
    internal val searchSpace = SearchSpace()

    /** A file the test names, resolved against its directory, with the line it is named on. */
    internal class Declared(val written: String, val path: Path, val line: Int)

    /** Simulates the system the RTSProfile [profile] describes (`rtcoord profile save` writes one). */
    public fun system(profile: String) {
        system = Declared(profile, directory.resolve(profile), line())
    }

    /**
     * Reads the IDL files in [directory] for the data types of the system's own, besides OpenRTM-aist's, as `rtcoord
     * sim --idl` does; once per directory.
     */
    public fun idl(directory: String) {
        idlDirectories += Declared(directory, this.directory.resolve(directory), line())
    }

    /** Runs the coordinator script [script] with [args] against the simulated system. */
    public fun coordinator(script: String, vararg args: String) {
        coordinator = Declared(script, directory.resolve(script), line())
        coordinatorArgs = args.toList()
    }

    /**
     * Narrows what `rtcoord test --explore` searches: which components and managers its faults are on, which faults,
     * the moments they are drawn at, and faults out of scope (`exclude { killManager() }`). Running the test without
     * `--explore` ignores it.
     */
    public fun explore(space: SearchSpace.() -> Unit) {
        searchSpace.apply(space)
    }

    /**
     * A scenario named [name]: the steps at the top of the file, then [steps], on a system and a coordinator of its
     * own. Each scenario is a test case of its own in reports.
     */
    public fun scenario(name: String, steps: Scenario.() -> Unit) {
        scenarios += Scenario(name, fileName, line()).apply(steps)
    }
}

/** A named scenario of a test file: its [Timeline] follows the steps written at the top of the file. */
public class Scenario
internal constructor(
    /** The scenario's name, which reports name its test case by. */
    public val name: String,
    fileName: String,
    /** The line of the test file it is declared on. */
    internal val declaredAt: Int,
) : Timeline(fileName)
