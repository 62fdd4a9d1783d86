package org.rtcoord.cli

/**
 * [value] as JSON: maps (string keys), lists, strings, numbers, booleans and null, which is all the
 * `--json` outputs hold. [pretty] indents by two spaces; otherwise everything is on one line, as
 * `rtcoord --json watch` prints one event per line.
 */
internal fun toJson(value: Any?, pretty: Boolean = true): String = buildString { writeJson(value, if (pretty) 0 else null) }

private fun StringBuilder.writeJson(value: Any?, indent: Int?) {
    when (value) {
        null -> append("null")
        is String -> writeString(value)
        is Boolean -> append(value)
        is Double -> if (value.isFinite()) append(value) else writeString(value.toString())
        is Number -> append(value)
        is Map<*, *> -> writeContainer('{', '}', value.entries, indent) { (key, item), inner ->
            writeString(key.toString())
            append(if (inner == null) ":" else ": ")
            writeJson(item, inner)
        }
        is Iterable<*> -> writeContainer('[', ']', value.toList(), indent) { item, inner -> writeJson(item, inner) }
        else -> writeString(value.toString())
    }
}

private fun <T> StringBuilder.writeContainer(open: Char, close: Char, items: Collection<T>, indent: Int?, writeItem: StringBuilder.(T, Int?) -> Unit) {
    append(open)
    if (items.isEmpty()) {
        append(close)
        return
    }
    val inner = indent?.plus(2)
    items.forEachIndexed { index, item ->
        if (index > 0) append(',')
        if (inner != null) append('\n').append(" ".repeat(inner))
        writeItem(item, inner)
    }
    if (indent != null) append('\n').append(" ".repeat(indent))
    append(close)
}

private fun StringBuilder.writeString(text: String) {
    append('"')
    for (c in text) {
        when {
            c == '"' -> append("\\\"")
            c == '\\' -> append("\\\\")
            c == '\n' -> append("\\n")
            c == '\r' -> append("\\r")
            c == '\t' -> append("\\t")
            c < ' ' -> append("\\u%04x".format(c.code))
            else -> append(c)
        }
    }
    append('"')
}
