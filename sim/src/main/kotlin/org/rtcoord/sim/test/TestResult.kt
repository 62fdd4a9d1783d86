package org.rtcoord.sim.test

import java.nio.file.Path
import kotlin.time.Duration

/** How one test file went: its failures as `file:line: what`, none when it passed, and the coordinator's log. */
public class TestResult(
    /** The test file. */
    public val file: Path,
    /** Each failure, `file:line: what`. */
    public val failures: List<String>,
    /** How long the test took, simulated system included. */
    public val duration: Duration,
    /** What the coordinator logged, one line a message. */
    public val log: List<String>,
) {
    /** Whether every expectation held. */
    public val passed: Boolean get() = failures.isEmpty()

    /** The test's name: its file name without `.test.kts`. */
    public val name: String get() = file.fileName.toString().removeSuffix(".test.kts")
}
