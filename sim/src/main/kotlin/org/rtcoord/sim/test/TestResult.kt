package org.rtcoord.sim.test

import kotlin.time.Duration

/**
 * How one scenario of a test file went: its [failures], none when it passed, the coordinator's [log] and the scenario's
 * [timeline]. A test file that cannot be run (it does not compile, names a file that is not there, a mode its
 * coordinator lacks) is one result, named after the file, with those failures.
 */
public class TestResult
internal constructor(
    /** The test file. */
    public val file: TestFile,
    /** The scenario's name; the file's [TestFile.name] for a file without scenarios or that could not be run. */
    public val scenario: String,
    /** Why it failed, each where and what; empty when it passed. */
    public val failures: List<TestFailure>,
    /** How long it took, the simulated system's start and stop included. */
    public val duration: Duration,
    /** What the coordinator logged, one line a message. */
    public val log: List<String>,
    /** What happened, in order, with times from the scenario's start. */
    public val timeline: List<TimelineEntry>,
) {
    /** Whether every expectation held, no invariant broke and no handler failed unexpectedly. */
    public val passed: Boolean
        get() = failures.isEmpty()

    /** The test file's name, then the scenario's when it has scenarios: `a/transient › laser breaks for good`. */
    public val name: String
        get() = if (scenario == file.name) file.name else "${file.name} › $scenario"

    override fun toString(): String = "${if (passed) "PASS" else "FAIL"} $name"
}
