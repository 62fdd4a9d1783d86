package org.rtcoord.dsl.internal

import java.nio.file.Path
import org.rtcoord.dsl.LiveCheck
import org.rtcoord.dsl.NameFinding
import org.rtcoord.dsl.ScriptCheck
import org.rtcoord.dsl.script.NameKind
import org.rtcoord.dsl.script.WrittenName

/**
 * Turns what a [LiveCheck] found missing into a [ScriptCheck] of [script], whose [text] writes [written]: each miss at
 * each place the text writes it (or where its text first appears), set apart when the script creates it itself.
 */
internal class Findings(private val script: Path, private val text: String, private val written: List<WrittenName>) {
    /**
     * Created components, by instance name (no `.rtc`), with the `create` that makes them; a type's `TYPE<n>` by
     * pattern.
     */
    private val createdNames =
        written
            .filter { it.kind == NameKind.CREATED_NAME && it.name != null }
            .associateBy { it.name!!.removeSuffix(".rtc") }
    private val createdTypes =
        written
            .filter { it.kind == NameKind.CREATED_TYPE && it.name != null }
            .map { Regex("${Regex.escape(it.name!!)}\\d+") to it }

    fun of(misses: Collection<LiveCheck.Miss>): ScriptCheck {
        val missing = mutableListOf<Pair<NameFinding, Boolean>>()
        val created = mutableListOf<NameFinding>()
        val seen = HashSet<String>()
        for (miss in misses) {
            for (at in places(miss)) {
                val finding =
                    creator(miss.name)?.let {
                        NameFinding(at, miss.name, "created by the script at ${script}:${it.line}")
                    }
                if (!seen.add("$at ${miss.name}")) continue
                if (finding != null) created += finding
                else missing += NameFinding(at, miss.name, miss.reason) to miss.rule
            }
        }
        val ordered = missing.sortedWith(compareBy(position) { it.first.at })
        val unchecked =
            written
                .filter { it.name == null }
                .map { NameFinding("$script:${it.position}", it.expression, "computed as the script runs") }
        return ScriptCheck(
            ordered.map { it.first },
            ordered.filter { it.second }.map { it.first },
            created.sortedWith(compareBy(position) { it.at }),
            unchecked,
        )
    }

    /** The `create` that makes component [name] (or the component of port [name]), if the script has one. */
    private fun creator(name: String): WrittenName? {
        val bare = name.substringAfterLast('/').substringBefore(':').removeSuffix(".rtc")
        return createdNames[bare] ?: createdTypes.firstOrNull { (pattern, _) -> pattern.matches(bare) }?.second
    }

    /**
     * Where [miss] is written: at its own place, each place the text passes it, or where it first appears in the text.
     */
    private fun places(miss: LiveCheck.Miss): List<String> {
        miss.at?.let {
            return listOf("$script:${it.position}")
        }
        val uses = written.filter { it.name == miss.name }
        if (uses.isNotEmpty()) return uses.map { "$script:${it.position}" }
        return listOf("$script:${positionOf(miss.name)}")
    }

    /** Where [name] first appears as a string literal, else its last `:` part (a port's name); else 1:1. */
    private fun positionOf(name: String): String {
        val at =
            listOf("\"$name\"", "\"${name.substringAfterLast(':')}\"").map { text.indexOf(it) }.firstOrNull { it >= 0 }
                ?: return "1:1"
        val lineStart = text.lastIndexOf('\n', at - 1) + 1
        return "${text.substring(0, at).count { it == '\n' } + 1}:${at - lineStart + 1}"
    }

    private companion object {
        /** Orders `file:line:col` by line, then column. */
        val position =
            Comparator<String> { a, b ->
                val (la, ca) = a.split(':').takeLast(2).map { it.toInt() }
                val (lb, cb) = b.split(':').takeLast(2).map { it.toInt() }
                compareValuesBy(la to ca, lb to cb, { it.first }, { it.second })
            }
    }
}
