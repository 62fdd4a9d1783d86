@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.sim.test

import java.nio.file.Path
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.dsl.script.ScriptSource

/** Where a loaded test file's steps are written, and what they say there: how failures name them. */
internal class TestSource(private val shown: Path, private val text: ScriptSource) {
    /** `file:line:col` of [step]. */
    fun at(step: TestStep): String = at(step.line, step.word)

    /** `file:line:col` of [word] on [line]. */
    fun at(line: Int, word: String): String = "$shown:$line:${text.column(line, word)}"

    /** What [step]'s braces hold, on one line, or [otherwise]. */
    fun condition(step: TestStep, otherwise: String = "the condition"): String =
        text.block(step.line, step.word) ?: otherwise
}
