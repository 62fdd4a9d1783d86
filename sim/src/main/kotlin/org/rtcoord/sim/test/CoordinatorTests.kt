package org.rtcoord.sim.test

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.DynamicTest
import java.nio.file.Path
import java.nio.file.Paths
import java.util.stream.Stream

/**
 * The JUnit 5 API: `*.test.kts` files as dynamic tests, one per file, each failing with its
 * `file:line: what` lines. From Kotlin, `@TestFactory fun coordinators() = CoordinatorTests.of("examples")`;
 * from Java, `@TestFactory Stream<DynamicTest> coordinators() { return CoordinatorTests.of("examples"); }`.
 */
public object CoordinatorTests {
    /** A test per `*.test.kts` file of [paths] (files, or directories whose test files are taken). */
    @JvmStatic
    public fun of(vararg paths: String): Stream<DynamicTest> = of(paths.map { Paths.get(it) })

    /** A test per `*.test.kts` file of [paths]. */
    @JvmStatic
    public fun of(paths: List<Path>): Stream<DynamicTest> {
        val runner = CoordinatorTestRunner(parallelism = 1)
        return runner.files(paths).stream().map { file ->
            DynamicTest.dynamicTest(file.fileName.toString().removeSuffix(".test.kts"), file.toUri()) {
                val result = runBlocking { runner.run(file) }
                if (!result.passed) throw AssertionError(result.failures.joinToString("\n"))
            }
        }
    }
}
