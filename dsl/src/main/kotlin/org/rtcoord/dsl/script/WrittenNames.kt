package org.rtcoord.dsl.script

/** What a name written in a script names. */
internal enum class NameKind {
    COMPONENT,
    PORT,
    MANAGER,
    CONTEXT,
    PROFILE,
    CREATED_TYPE,
    CREATED_NAME,
}

/**
 * One name a script's text passes to a word of the DSL, where it is written ([line], [column]: of its opening quote,
 * 1-based). [name] is null when the argument is built at run time (a variable, a string template, a port of a component
 * known only at run time): [expression] is what was written then.
 */
internal class WrittenName(
    val kind: NameKind,
    val name: String?,
    val expression: String,
    val line: Int,
    val column: Int,
) {
    val position: String
        get() = "$line:$column"
}

/**
 * The names a script's text passes to `component`, `port`, `manager`, `context`, `connect`, `disconnect`, the network's
 * `active`, `connected` and `configSet`, a supervisor's `child`, `profile`, `restoreProfile`, `checkProfile` and a
 * manager's `create`, anywhere in the script, handlers included: what `check` can look up before anything runs, which
 * the evaluated plan alone does not show (a handler's names are known only when it runs). Read from the text, comments
 * skipped.
 */
internal object WrittenNames {
    private val call =
        Regex(
            """(?<![\w$])(component|port|manager|context|connect|disconnect|active|connected|configSet|child|profile|restoreProfile|checkProfile|create)\s*\("""
        )
    private val literal = Regex("""^"((?:[^"\\$]|\\.)*)"$""")
    private val namedArgument = Regex("""^\w+\s*=(?!=)\s*""")
    private val componentReceiver = Regex("""component\s*\(\s*"([^"\\$]*)"\s*\)\s*\.\s*$""")

    fun read(text: String): List<WrittenName> {
        val code = withoutComments(text)
        val strings = strings(code)
        val found = mutableListOf<WrittenName>()
        for (match in call.findAll(code)) {
            if (strings.any { match.range.first in it }) continue
            val word = match.groupValues[1]
            val arguments = arguments(code, match.range.last + 1) ?: continue
            val before = code.substring(0, match.range.first).trimEnd()
            val member = before.endsWith(".")
            fun use(kind: NameKind, argument: Argument, name: String? = argument.literal) {
                val (line, column) = lineAndColumn(code, argument.offset)
                found += WrittenName(kind, name, argument.text, line, column)
            }
            when (word) {
                // component(type = "laser") names a type, which covers any number of components, as a glob does.
                "component",
                "child" ->
                    arguments
                        .firstOrNull()
                        ?.takeIf { it.named == null || it.named == "name" }
                        ?.let { if (!member) use(NameKind.COMPONENT, it) }
                "port" ->
                    arguments.firstOrNull()?.let { argument ->
                        if (!member) use(NameKind.PORT, argument)
                        else {
                            // component("x").port("p") names x:p; a port of anything else is known only when it runs.
                            val owner = componentReceiver.find(before)?.groupValues?.get(1)
                            use(
                                NameKind.PORT,
                                argument,
                                if (owner != null && argument.literal != null) "$owner:${argument.literal}" else null,
                            )
                        }
                    }
                "manager" ->
                    if (!member) {
                        val argument = arguments.firstOrNull()
                        if (argument != null) use(NameKind.MANAGER, argument)
                        else use(NameKind.MANAGER, Argument("manager()", match.range.first, "manager.mgr"))
                    }
                "context" -> arguments.firstOrNull()?.let { if (!member) use(NameKind.CONTEXT, it) }
                "connect",
                "disconnect",
                "connected" ->
                    arguments
                        .take(2)
                        .filter { it.literal != null || !it.text.isCall() }
                        .forEach { use(NameKind.PORT, it) }
                "active" -> arguments.forEach { use(NameKind.COMPONENT, it) }
                "configSet" -> arguments.firstOrNull()?.let { use(NameKind.COMPONENT, it) }
                "profile",
                "restoreProfile",
                "checkProfile" -> arguments.firstOrNull()?.let { use(NameKind.PROFILE, it) }
                "create" ->
                    if (member) {
                        arguments.getOrNull(0)?.let { use(NameKind.CREATED_TYPE, it) }
                        arguments.getOrNull(1)?.takeIf { it.text != "null" }?.let { use(NameKind.CREATED_NAME, it) }
                    }
            }
        }
        return found.sortedWith(compareBy({ it.line }, { it.column }))
    }

    /** A port given as `port(...)`, `x.port(...)` or another call is read where that call is written. */
    private fun String.isCall(): Boolean = trimEnd().endsWith(")")

    /**
     * One argument of a call: its [text] (after `name =` when [named]), where it starts, and the string it is, if a
     * literal.
     */
    private class Argument(val text: String, val offset: Int, val literal: String?, val named: String? = null)

    private fun argument(text: String, offset: Int, named: String?): Argument =
        Argument(text, offset, literal.find(text)?.groupValues?.get(1)?.let(::unescape), named)

    /**
     * The arguments of the call whose `(` ends just before [start], split at its top-level commas; null when it does
     * not close.
     */
    private fun arguments(code: String, start: Int): List<Argument>? {
        val arguments = mutableListOf<Argument>()
        var depth = 0
        var from = start
        var i = start
        fun add(end: Int) {
            val raw = code.substring(from, end)
            val lead = raw.length - raw.trimStart().length
            var text = raw.trim()
            var offset = from + lead
            var name: String? = null
            namedArgument.find(text)?.let { named ->
                offset += named.value.length
                name = named.value.substringBefore('=').trim()
                text = text.substring(named.value.length)
            }
            if (text.isNotEmpty()) arguments += argument(text, offset, name)
        }
        while (i < code.length) {
            when (code[i]) {
                '"' -> i = endOfString(code, i)
                '\'' -> i = code.indexOf('\'', i + 2).takeIf { it >= 0 } ?: return null
                '(',
                '[',
                '{' -> depth++
                ')',
                ']',
                '}' ->
                    if (depth == 0) {
                        add(i)
                        return arguments
                    } else depth--
                ',' ->
                    if (depth == 0) {
                        add(i)
                        from = i + 1
                    }
            }
            i++
        }
        return null
    }

    /** The index of the closing quote of the string that opens at [start] (raw strings included). */
    private fun endOfString(code: String, start: Int): Int {
        if (code.startsWith("\"\"\"", start))
            return (code.indexOf("\"\"\"", start + 3).takeIf { it >= 0 } ?: code.length - 3) + 2
        var i = start + 1
        while (i < code.length && code[i] != '"') {
            if (code[i] == '\\') i++ else if (code.startsWith("\${", i)) i = closing(code, i + 1)
            i++
        }
        return i
    }

    /** The index of the `}` that closes the `{` at [open]. */
    private fun closing(code: String, open: Int): Int {
        var depth = 0
        var i = open
        while (i < code.length) {
            when (code[i]) {
                '{' -> depth++
                '}' -> if (--depth == 0) return i
                '"' -> i = endOfString(code, i)
            }
            i++
        }
        return code.length
    }

    /** Where [code]'s string literals are, quotes included. */
    private fun strings(code: String): List<IntRange> {
        val ranges = mutableListOf<IntRange>()
        var i = 0
        while (i < code.length) {
            if (code[i] == '"') {
                val end = endOfString(code, i)
                ranges += i..end
                i = end
            } else if (code[i] == '\'') {
                i = code.indexOf('\'', i + 2).takeIf { it >= 0 } ?: code.length
            }
            i++
        }
        return ranges
    }

    /** [text] with its comments blanked out, every other character where it was. */
    private fun withoutComments(text: String): String {
        val out = StringBuilder(text)
        var i = 0
        while (i < text.length) {
            when {
                text[i] == '"' -> i = endOfString(text, i)
                text[i] == '\'' -> i = text.indexOf('\'', i + 2).takeIf { it >= 0 } ?: text.length
                text.startsWith("//", i) -> while (i < text.length && text[i] != '\n') out.setCharAt(i++, ' ')
                text.startsWith("/*", i) -> {
                    val end = text.indexOf("*/", i + 2).let { if (it < 0) text.length else it + 2 }
                    while (i < end) {
                        if (text[i] != '\n') out.setCharAt(i, ' ')
                        i++
                    }
                    continue
                }
            }
            i++
        }
        return out.toString()
    }

    private fun lineAndColumn(text: String, offset: Int): Pair<Int, Int> {
        val lineStart = text.lastIndexOf('\n', offset - 1) + 1
        return (text.substring(0, offset).count { it == '\n' } + 1) to (offset - lineStart + 1)
    }

    private fun unescape(text: String): String = text.replace(Regex("""\\(.)""")) { it.groupValues[1] }
}
