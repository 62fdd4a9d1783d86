package org.rtcoord.sim.test

/**
 * Marks the receivers of a `*.test.kts`: inside `scenario { }`, `at(...) { }` or `expect { }` only the words of that
 * block are in scope, so that `expect` cannot be written inside a fault block by accident.
 */
@DslMarker public annotation class TestDsl
