package org.rtcoord.sim.test

import org.junit.jupiter.api.DynamicTest
import org.junit.jupiter.api.TestFactory
import java.util.stream.Stream

/** The JUnit 5 API runs the examples' tests, a dynamic test per `*.test.kts` file. */
class CoordinatorTestsTest {
    @TestFactory
    fun examples(): Stream<DynamicTest> = CoordinatorTests.of("../examples")
}
