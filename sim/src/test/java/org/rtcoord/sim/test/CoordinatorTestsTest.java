package org.rtcoord.sim.test;

import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.TestFactory;

/** The JUnit 5 API, from Java as its KDoc shows it: the examples' tests, a container per {@code *.test.kts} file, a test per scenario. */
class CoordinatorTestsTest {
    @TestFactory
    Stream<DynamicNode> examples() {
        return CoordinatorTests.of("../examples");
    }
}
