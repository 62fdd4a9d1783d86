package org.rtcoord.sim.explore

import java.nio.file.Files
import java.nio.file.Path
import org.rtcoord.sim.test.LoadedTest
import org.rtcoord.sim.test.TestFailure

/**
 * A failure exploring found, written as a regression test next to the test it was found in:
 * `NAME.found-SEED-INDEX.test.kts`, the test's text with its other scenarios left out and the schedule in a `meanwhile
 * { }` of the failing scenario (at the end of a file without scenarios), headed by how it was found and the failure it
 * shows. It fails as written while the coordinator has the fault, and passes once it is fixed.
 */
internal object FoundTest {
    /** Where the test for [schedule] found in [test] is written. */
    fun path(test: LoadedTest, schedule: Schedule): Path {
        val name = test.file.path.fileName.toString().removeSuffix(".test.kts")
        return test.file.path.resolveSibling("$name.found-${schedule.seed}-${schedule.index}.test.kts")
    }

    /** Writes the test of [smallest], shrunk from [drawn], which fails with [failure]; returns its path. */
    fun write(test: LoadedTest, drawn: Schedule, smallest: Schedule, failure: TestFailure, replay: String): Path {
        val path = path(test, smallest)
        Files.writeString(path, text(Files.readString(test.file.path), test, drawn, smallest, failure, replay))
        return path
    }

    fun text(
        source: String,
        test: LoadedTest,
        drawn: Schedule,
        smallest: Schedule,
        failure: TestFailure,
        replay: String,
    ): String {
        val header =
            listOf(
                "// Found by `rtcoord test --explore` in ${test.file.path.fileName}, run ${smallest.key}, shrunk from ${drawn.faults.size} " +
                    "fault(s) to ${smallest.faults.size}; replay it with `$replay`.",
                "// While the coordinator has the fault, this test fails as the exploration did:",
                "//   ${failure.toString().replace('\n', ' ')}",
            )
        val meanwhile = listOf("meanwhile {") + smallest.faults.map { "    ${it.written}" } + "}"
        val blocks = test.scenarioLines.mapNotNull { ScenarioBlocks.block(source, it) }
        val mine = smallest.scenario.declaredAt?.let { at -> blocks.firstOrNull { it.line == at } }
        val kept = StringBuilder()
        var offset = 0
        for (block in blocks.sortedBy { it.start }) {
            kept.append(source, offset, block.start)
            if (block === mine) {
                val indent = " ".repeat(block.indent + 4)
                kept.append(source, block.start, block.bodyStart)
                kept.append("\n").append(meanwhile.joinToString("\n") { indent + it })
                kept.append(source, block.bodyStart, block.end)
            }
            offset = block.end
        }
        kept.append(source.substring(offset))
        val body = kept.toString().trimEnd() + if (mine == null) "\n\n" + meanwhile.joinToString("\n") else ""
        return (header + "" + body.replace(Regex("\n{3,}"), "\n\n")).joinToString("\n") + "\n"
    }
}

/**
 * The `scenario("...") { ... }` calls of a test's text, found by the line they start on: where each begins and ends,
 * for [FoundTest] to keep one and leave the others out. Strings, characters and comments are skipped, so braces in them
 * do not count.
 */
internal object ScenarioBlocks {
    /**
     * A call from [start] (its line's start) to [end] (past its closing brace and line end); its body opens at
     * [bodyStart].
     */
    class Block(val line: Int, val start: Int, val bodyStart: Int, val end: Int, val indent: Int)

    fun block(source: String, line: Int): Block? {
        var lineStart = 0
        repeat(line - 1) { lineStart = source.indexOf('\n', lineStart).takeIf { it >= 0 }?.plus(1) ?: return null }
        val word = source.indexOf("scenario", lineStart).takeIf { it >= 0 } ?: return null
        var i = word
        var depth = 0
        var bodyStart = -1
        while (i < source.length) {
            val skipped = skip(source, i)
            if (skipped != i) {
                i = skipped
                continue
            }
            when (source[i]) {
                '(',
                '{' -> {
                    if (source[i] == '{' && depth == 0 && bodyStart < 0) bodyStart = i + 1
                    depth++
                }
                ')',
                '}' -> {
                    depth--
                    if (depth == 0 && source[i] == '}' && bodyStart >= 0) {
                        val lineEnd = source.indexOf('\n', i).let { if (it < 0) source.length else it + 1 }
                        return Block(line, lineStart, bodyStart, lineEnd, word - lineStart)
                    }
                }
            }
            i++
        }
        return null
    }

    /** Past the string, character or comment starting at [i], or [i] when none does. */
    private fun skip(source: String, i: Int): Int =
        when {
            source.startsWith("//", i) -> source.indexOf('\n', i).let { if (it < 0) source.length else it }
            source.startsWith("/*", i) -> source.indexOf("*/", i + 2).let { if (it < 0) source.length else it + 2 }
            source.startsWith("\"\"\"", i) ->
                source.indexOf("\"\"\"", i + 3).let { if (it < 0) source.length else it + 3 }
            source[i] == '"' || source[i] == '\'' -> {
                var j = i + 1
                while (j < source.length && source[j] != source[i]) j += if (source[j] == '\\') 2 else 1
                j + 1
            }
            else -> i
        }
}
