package org.rtcoord.cli

/**
 * A decoded sample's members on one line, as `print` shows them: `{position: {x: 1.0, y: 2.0}, heading: 0.5}`; a
 * sequence longer than [SHOWN] elements by its first ones and its length, so a laser scan or a camera image stays one
 * readable line.
 */
internal object MemberText {
    private const val SHOWN = 8

    fun of(value: Any?): String = buildString { appendValue(value) }

    private fun StringBuilder.appendValue(value: Any?) {
        when (value) {
            is Map<*, *> -> {
                append('{')
                value.entries.forEachIndexed { index, (name, member) ->
                    if (index > 0) append(", ")
                    append(name.toString()).append(": ")
                    appendValue(member)
                }
                append('}')
            }
            is List<*> -> {
                append('[')
                value.take(SHOWN).forEachIndexed { index, element ->
                    if (index > 0) append(' ')
                    appendValue(element)
                }
                if (value.size > SHOWN) append(" ... (").append(value.size.toString()).append(" values)")
                append(']')
            }
            is String -> append('"').append(value).append('"')
            else -> append(value)
        }
    }
}
