package org.rtcoord.bench

/**
 * Untimed work in rounds of [round], until two rounds in a row kept the JIT compiling for under 1% of their time, or
 * [limit] pieces of work were done: C2 still compiles a path after thousands of runs of it, and a run timed while it
 * does measures the JVM's warm-up (and waits for a core), not the library.
 */
internal class JitWarmUp(private val round: Int, private val limit: Int) {
    init {
        require(round > 0 && limit >= 0) { "a warm-up needs rounds of at least 1 and a limit of at least 0" }
    }

    /** Does [work] until the JIT is quiet; returns how many times it did it. */
    suspend fun make(work: suspend () -> Unit): Int {
        var made = 0
        var quietRounds = 0
        while (made < limit && quietRounds < 2) {
            val pieces = minOf(round, limit - made)
            val stretch = JitCompilation.during { repeat(pieces) { work() } }
            made += pieces
            val quiet = stretch.compiledMillis?.let { it * 100 < stretch.millis } ?: false
            quietRounds = if (quiet) quietRounds + 1 else 0
        }
        return made
    }
}
