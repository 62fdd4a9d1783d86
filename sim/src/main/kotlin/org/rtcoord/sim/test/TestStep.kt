package org.rtcoord.sim.test

import kotlin.time.Duration

/** One step of a test's timeline, with the line of the test file it is written on. */
internal sealed class TestStep(val line: Int) {
    /** The word the step is written with, which its column and source text are found by. */
    abstract val word: String

    class At(line: Int, val time: Duration, val faults: Faults.() -> Unit) : TestStep(line) {
        override val word: String
            get() = "at"
    }

    /** Faults applied alongside the steps, each at its time from the scenario's start: see [Meanwhile]. */
    class Meanwhile(line: Int, val faults: List<At>) : TestStep(line) {
        override val word: String
            get() = "meanwhile"
    }

    class Expect(line: Int, val within: Duration, val condition: suspend Observation.() -> Boolean) : TestStep(line) {
        override val word: String
            get() = "expect"
    }

    class ExpectMode(line: Int, val machine: String, val mode: String, val within: Duration) : TestStep(line) {
        override val word: String
            get() = "expectMode"
    }

    class ExpectLog(line: Int, val text: String, val within: Duration) : TestStep(line) {
        override val word: String
            get() = "expectLog"
    }

    class ExpectHandlerFailure(line: Int, val text: String, val within: Duration) : TestStep(line) {
        override val word: String
            get() = "expectHandlerFailure"
    }

    /** Checked when the timeline ends. */
    class NoRestarts(line: Int, val component: String) : TestStep(line) {
        override val word: String
            get() = "expectNoRestartsOf"
    }

    class Invariant(line: Int, val kind: Kind, val condition: suspend Observation.() -> Boolean) : TestStep(line) {
        enum class Kind {
            ALWAYS,
            NEVER,
        }

        override val word: String
            get() = kind.name.lowercase()

        /** Whether [value], what the condition returned, keeps the invariant. */
        fun keptBy(value: Boolean): Boolean = if (kind == Kind.ALWAYS) value else !value
    }
}
