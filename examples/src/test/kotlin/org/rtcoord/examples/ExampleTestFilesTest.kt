package org.rtcoord.examples

import org.junit.jupiter.api.TestFactory
import org.rtcoord.sim.test.CoordinatorTests

/**
 * Every `*.test.kts` of the examples passes on its simulated system, as `rtcoord test examples/` runs them: a container
 * per file, a test per scenario, the regression tests exploring found (`*.found-*.test.kts`) among them. Here, beside
 * cli's tests, rather than through the command (cli's SimAndTestCommandTest runs two of them to check what the command
 * prints). Three scenarios at a time: each mostly waits on the robot's clock.
 */
class ExampleTestFilesTest {
    @TestFactory fun `every example test file`() = CoordinatorTests.of(3, ".")
}
