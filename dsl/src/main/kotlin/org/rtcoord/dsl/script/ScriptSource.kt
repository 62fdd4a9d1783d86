package org.rtcoord.dsl.script

import java.nio.file.Files
import java.nio.file.Path
import org.rtcoord.InternalRtcoordApi

/**
 * A script's text, for what messages quote of it: the column a word is written at, and the block of code a call passes
 * in braces, such as a rule's guard (`where { component("x").state() != ACTIVE }`) or a test's condition
 * (`expect(within = 1.seconds) { component("x").state() == ERROR }`).
 */
@InternalRtcoordApi
public class ScriptSource(private val text: String) {
    private val starts: List<Int> = listOf(0) + text.indices.filter { text[it] == '\n' }.map { it + 1 }

    /** The 1-based column of [word] on [line], as a whole word; 1 when it is not there. */
    public fun column(line: Int, word: String): Int = wordAt(line, word)?.let { it - starts[line - 1] + 1 } ?: 1

    /** What the braces after [word] on [line] hold, on one line; null when it cannot be found. */
    public fun block(line: Int, word: String): String? {
        var i = wordAt(line, word) ?: return null
        while (i < text.length && text[i] != '{') {
            if (text[i] == '"') i = endOfString(i)
            i++
        }
        if (i >= text.length) return null
        val open = i
        var depth = 0
        while (i < text.length) {
            when (text[i]) {
                '"' -> i = endOfString(i)
                '\'' -> i = text.indexOf('\'', i + 2).takeIf { it >= 0 } ?: return null
                '{' -> depth++
                '}' -> if (--depth == 0) return text.substring(open + 1, i).trim().replace(Regex("\\s+"), " ")
            }
            i++
        }
        return null
    }

    private fun wordAt(line: Int, word: String): Int? {
        if (line < 1 || line > starts.size) return null
        val start = starts[line - 1]
        val end = starts.getOrNull(line)?.minus(1) ?: text.length
        return Regex("(?<![\\w$])${Regex.escape(word)}(?![\\w$])")
            .find(text.substring(start, end))
            ?.range
            ?.first
            ?.plus(start)
    }

    public companion object {
        /** The text of [script], or null when it cannot be read. */
        public fun read(script: Path): ScriptSource? =
            try {
                ScriptSource(Files.readString(script))
            } catch (e: java.io.IOException) {
                null
            }
    }

    /** The index of the quote that closes the string opening at [start], raw strings included. */
    private fun endOfString(start: Int): Int {
        if (text.startsWith("\"\"\"", start))
            return (text.indexOf("\"\"\"", start + 3).takeIf { it >= 0 } ?: (text.length - 3)) + 2
        var i = start + 1
        while (i < text.length && text[i] != '"') {
            if (text[i] == '\\') i++
            i++
        }
        return i
    }
}
