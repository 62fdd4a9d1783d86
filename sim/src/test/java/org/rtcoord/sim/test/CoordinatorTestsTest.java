package org.rtcoord.sim.test;

import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/** The JUnit 5 API, from Java as its KDoc shows it: the examples' tests, a dynamic test per {@code *.test.kts} file. */
class CoordinatorTestsTest {
    @TestFactory
    Stream<DynamicTest> examples() {
        return CoordinatorTests.of("../examples");
    }
}
