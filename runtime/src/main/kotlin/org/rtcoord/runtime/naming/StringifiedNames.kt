package org.rtcoord.runtime.naming

import org.omg.CosNaming.NamingContextPackage.InvalidName

/**
 * The CosNaming stringified name syntax: components separated by `/`, id and kind by `.`, and `\` escaping any of those
 * three characters inside an id or kind.
 */
internal object StringifiedNames {
    private const val SEPARATOR = '/'
    private const val KIND = '.'
    private const val ESCAPE = '\\'
    private val special = setOf(SEPARATOR, KIND, ESCAPE)

    fun format(name: List<NameKey>): String =
        name.joinToString(SEPARATOR.toString()) { key ->
            if (key.kind.isEmpty()) escape(key.id) else escape(key.id) + KIND + escape(key.kind)
        }

    /** The name [sn] stands for; raises InvalidName for anything the syntax (or [NameKey]) rejects. */
    fun parse(sn: String): List<NameKey> = split(sn, SEPARATOR).map(::component)

    private fun component(text: String): NameKey {
        val parts = split(text, KIND)
        val key =
            when (parts.size) {
                1 -> NameKey(unescape(parts[0]), "")
                // "id." is malformed: an empty kind is written without the dot.
                2 -> NameKey(unescape(parts[0]), unescape(parts[1]).ifEmpty { throw InvalidName() })
                else -> throw InvalidName()
            }
        if (key.id.isEmpty()) throw InvalidName()
        return key
    }

    /** [text] cut at every [separator] that is not escaped; the pieces keep their escapes. */
    private fun split(text: String, separator: Char): List<String> {
        val pieces = ArrayList<String>()
        var start = 0
        var i = 0
        while (i < text.length) {
            when (text[i]) {
                ESCAPE -> i++
                separator -> {
                    pieces += text.substring(start, i)
                    start = i + 1
                }
            }
            i++
        }
        pieces += text.substring(start)
        return pieces
    }

    private fun unescape(text: String): String = buildString {
        var i = 0
        while (i < text.length) {
            if (text[i] == ESCAPE) {
                val escaped = text.getOrNull(i + 1)
                if (escaped == null || escaped !in special) throw InvalidName()
                append(escaped)
                i += 2
            } else {
                append(text[i])
                i++
            }
        }
    }

    private fun escape(text: String): String = buildString {
        for (c in text) {
            if (c in special) append(ESCAPE)
            append(c)
        }
    }
}
