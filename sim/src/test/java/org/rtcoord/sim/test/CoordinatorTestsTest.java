package org.rtcoord.sim.test;

import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.TestFactory;

/**
 * The JUnit 5 API, from Java as its KDoc shows it: a container per {@code *.test.kts} file, a test per scenario, one
 * after another or several at a time. Two of the examples' files; examples' ExampleTestFilesTest runs them all.
 */
class CoordinatorTestsTest {
    @TestFactory
    Stream<DynamicNode> examples() {
        return CoordinatorTests.of("../examples/frozen-laser.test.kts");
    }

    @TestFactory
    Stream<DynamicNode> examplesTwoAtATime() {
        return CoordinatorTests.of(2, "../examples/modes.test.kts");
    }
}
