package org.rtcoord

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlin.streams.toList
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test

/**
 * Each fact about the live system has one owner (the table in docs/architecture.md): a second place that keeps a copy
 * of it (a component's state, what a read found, whether a component, a manager or a name server answers) or that works
 * out "each component once, at its canonical path" from the listings for itself fails here, naming the line, the fact
 * and its owner. Reads the main sources of core, dsl, cli and sim (runtime is the simulated system, not rtcoord's view
 * of one).
 */
class FactOwnersTest {
    /** A fact, how a place that keeps it looks, and the files allowed to keep it, each with why. */
    private class Fact(
        val what: String,
        val owner: String,
        val keeps: (Declaration) -> Boolean,
        val allowed: Map<String, String>,
    )

    /** A property of a class or file (not a local): what a copy of a fact would be. */
    private class Declaration(val file: String, val line: Int, val name: String, val text: String) {
        /** Its declared type and what its initializer makes (not the arguments it makes it with). */
        val shape: String
            get() = text.substringBefore('=') + text.substringAfter('=', "").trim().substringBefore('(')

        /** Whether it holds something that changes: a `var`, or a `val` holding a mutable container. */
        val mutable: Boolean
            get() = Regex("""\bvar\b""").containsMatchIn(text.substringBefore('=')) || MUTABLE.containsMatchIn(shape)

        override fun toString() = "$file:$line: $text"
    }

    private val facts =
        listOf(
            Fact(
                "a component's lifecycle state",
                "the tree's model, core/src/main/kotlin/org/rtcoord/internal/model/SystemModel.kt (read it through RtcTree.snapshot() or follow)",
                { it.mutable && "LifeCycle" in it.shape },
                mapOf(
                    "core/src/main/kotlin/org/rtcoord/internal/model/SystemModel.kt" to
                        "the owner: the states as the tree's events tell them",
                    "core/src/main/kotlin/org/rtcoord/internal/events/StateTracker.kt" to
                        "the machine that decides what is published; the model records what it publishes",
                    "core/src/main/kotlin/org/rtcoord/internal/events/StateProbe.kt" to
                        "a poll round's replies in flight, before the machine has them",
                    "sim/src/main/kotlin/org/rtcoord/sim/test/SystemModel.kt" to
                        "a scenario's record event by event, folded from RtcTree.follow: an invariant is read against each event's outcome",
                ),
            ),
            Fact(
                "what a component answered when last read",
                "the component's snapshot flow, core/src/main/kotlin/org/rtcoord/internal/ComponentObject.kt (ComponentNode.snapshots)",
                { it.mutable && Regex("""\bComponent(Snapshot|Summary)\b""").containsMatchIn(it.shape) },
                mapOf(
                    "core/src/main/kotlin/org/rtcoord/internal/ComponentObject.kt" to
                        "the owner: the latest read, published as ComponentNode.snapshots",
                    "core/src/main/kotlin/org/rtcoord/internal/events/ComponentWatch.kt" to
                        "the machine's last read, which the next is compared with to make events",
                ),
            ),
            Fact(
                "whether a component answers",
                "the tree's model, core/src/main/kotlin/org/rtcoord/internal/model/SystemModel.kt (ComponentEntry.alive)",
                {
                    it.mutable && Regex("""(?i)(dead(?!line)|gone|alive|unreachable|zombie)""").containsMatchIn(it.name)
                },
                mapOf(
                    "core/src/main/kotlin/org/rtcoord/internal/model/SystemModel.kt" to
                        "the owner: components found dead, as the tree's events tell them",
                    "sim/src/main/kotlin/org/rtcoord/sim/test/SystemModel.kt" to
                        "a scenario's record event by event, folded from RtcTree.follow",
                ),
            ),
            Fact(
                "which name servers and managers answer",
                "the tree's model, core/src/main/kotlin/org/rtcoord/internal/model/SystemModel.kt (SystemSnapshot.nameServers, deadManagers)",
                {
                    it.mutable &&
                        (Regex("""(?i)(outage|lost|returned|died|deadManager)""").containsMatchIn(it.name) ||
                            Regex("""\b(ManagerDied|NameServerLost)\b""").containsMatchIn(it.shape))
                },
                mapOf(
                    "core/src/main/kotlin/org/rtcoord/internal/model/SystemModel.kt" to
                        "the owner: outages as the tree's events tell them"
                ),
            ),
        )

    @Test
    fun `each fact is kept by its owner alone`() {
        val declarations = sources().flatMap { (file, text) -> declarations(file, text) }
        assertTrue(declarations.size > 300, "too few declarations read (${declarations.size}): the scan is broken")
        val copies = facts.flatMap { fact ->
            declarations
                .filter { fact.keeps(it) && it.file !in fact.allowed }
                .map { copy ->
                    "$copy\n    keeps ${fact.what}, whose one owner is ${fact.owner}: derive from it, or make this file an owner " +
                        "in docs/architecture.md's table and in FactOwnersTest, with the reason"
                }
        }
        assertEquals("", copies.joinToString("\n"), "a second owner of a fact")
    }

    @Test
    fun `every owner allowed still keeps its fact`() {
        val declarations = sources().flatMap { (file, text) -> declarations(file, text) }
        val stale = facts.flatMap { fact ->
            fact.allowed.keys
                .filter { file -> declarations.none { it.file == file && fact.keeps(it) } }
                .map { "$it no longer keeps ${fact.what}: take it off the owners" }
        }
        assertEquals("", stale.joinToString("\n"))
    }

    @Test
    fun `one walk finds each component once at its canonical path`() {
        val walks =
            sources().flatMap { (file, text) ->
                text
                    .lines()
                    .withIndex()
                    .filter { (_, line) -> ONE_PER_COMPONENT.any { it.containsMatchIn(line) } }
                    .filter { file !in WALKERS }
                    .map { (index, line) -> "$file:${index + 1}: ${line.trim()}" }
            }
        assertEquals(
            "",
            walks.joinToString("\n") {
                "$it\n    keeps one node per component itself: take componentsOnce (core/src/main/kotlin/org/rtcoord/internal/ComponentsOnce.kt)"
            },
            "a second walk for each component once",
        )
    }

    @Test
    fun `the scan sees a copy where one is kept and not where none is`() {
        val copy =
            """
            internal class Copy(private val first: LifeCycle) {
                private val states = HashMap<String, LifeCycle>()
                var last: LifeCycle = first
                val overall: LifeCycle get() = first
                fun read(): LifeCycle {
                    val local = ArrayList<LifeCycle>()
                    return local.first()
                }
            }
            """
                .trimIndent()
        val found = declarations("Copy.kt", copy)
        assertEquals(
            listOf("states", "last"),
            found.filter { facts.first().keeps(it) }.map { it.name },
            found.joinToString("\n"),
        )
    }

    /**
     * The main Kotlin sources of the modules that make rtcoord's view of a system, by path from the repository's root.
     */
    private fun sources(): List<Pair<String, String>> {
        val root = Paths.get("..").toAbsolutePath().normalize()
        return MODULES.flatMap { module ->
            val dir = root.resolve("$module/src/main/kotlin")
            assertTrue(Files.isDirectory(dir), "no sources at $dir")
            Files.walk(dir)
                .use { paths -> paths.filter { it.toString().endsWith(".kt") }.toList() }
                .map { path: Path -> root.relativize(path).toString().replace('\\', '/') to Files.readString(path) }
        }
    }

    private companion object {
        val MODULES = listOf("core", "dsl", "cli", "sim")

        val MUTABLE =
            Regex(
                """\b(Mutable\w*|HashMap|LinkedHashMap|ConcurrentHashMap|HashSet|LinkedHashSet|ArrayList|ArrayDeque|EnumMap|AtomicReference|newKeySet|mutable\w*Of|arrayOfNulls)\b"""
            )

        /** The ways of keeping one node of each component among many. */
        val ONE_PER_COMPONENT =
            listOf(
                Regex("""kept\.any \{ it\.isSameComponent"""),
                Regex("""putIfAbsent\(\w+\.component\b"""),
                Regex("""groupBy \{ it\.component \}"""),
            )

        val WALKERS =
            setOf(
                "core/src/main/kotlin/org/rtcoord/internal/ComponentsOnce.kt",
                // Watching includes each component once as the listings of a subscription arrive, concurrently.
                "core/src/main/kotlin/org/rtcoord/internal/events/Watcher.kt",
            )

        /**
         * The properties of [text] (class members, constructor properties, top-level ones; no locals), read with
         * comments and string literals left out and braces counted: a brace opened after `class`, `object` or
         * `interface` (and no `fun`, `init` or accessor after it) opens a body of members, any other a block of code.
         */
        fun declarations(file: String, text: String): List<Declaration> {
            val found = ArrayList<Declaration>()
            val bodies = ArrayDeque<Boolean>() // true: a body of members
            var header = StringBuilder()
            for ((index, line) in withoutCommentsAndStrings(text).lines().withIndex()) {
                if (bodies.lastOrNull() != false) {
                    MEMBER.find(line)?.let { found += Declaration(file, index + 1, it.groupValues[1], line.trim()) }
                    if (CLASS.containsMatchIn(line)) {
                        PARAMETER.findAll(line.substringAfter('(', "")).forEach {
                            found += Declaration(file, index + 1, it.groupValues[1], it.value.trim())
                        }
                    }
                }
                for (char in line) {
                    when (char) {
                        '{' -> {
                            val kind = CLASS.findAll(header).lastOrNull()
                            bodies.addLast(kind != null && !CODE.containsMatchIn(header.substring(kind.range.first)))
                            header = StringBuilder()
                        }
                        '}' -> {
                            bodies.removeLastOrNull()
                            header = StringBuilder()
                        }
                        else -> header.append(char)
                    }
                }
                header.append('\n')
            }
            return found.filterNot { "get()" in it.text || Regex("""\bby lazy\b""").containsMatchIn(it.text) }
        }

        val MEMBER =
            Regex(
                """^\s*(?:@\w+(?:\([^)]*\))?\s+)*(?:(?:private|internal|public|protected|override|open|final|abstract|lateinit|const)\s+)*(?:val|var)\s+(\w+)"""
            )
        val PARAMETER =
            Regex("""(?:(?:private|internal|public|protected|override)\s+)*\b(?:val|var)\s+(\w+)\s*:\s*[^,)]+""")
        val CLASS = Regex("""(?<!::)\b(class|object|interface)\b""")
        val CODE = Regex("""\b(fun|init)\b|\bget\(\)|\bset\(""")

        /** [text] with comments and the contents of string literals (templates too) blanked, lines kept. */
        fun withoutCommentsAndStrings(text: String): String {
            val out = StringBuilder(text.length)
            fun keepLines(from: Int, to: Int) = text.substring(from, to).forEach { if (it == '\n') out.append('\n') }
            // Where the string literal starting at [start] ends, past its closing quotes.
            fun stringEnd(start: Int): Int {
                val raw = text.startsWith("\"\"\"", start)
                var i = start + if (raw) 3 else 1
                while (i < text.length) {
                    when {
                        raw && text.startsWith("\"\"\"", i) -> return i + 3
                        !raw && text[i] == '"' -> return i + 1
                        !raw && text[i] == '\\' -> i += 2
                        text.startsWith("\${", i) -> {
                            var depth = 1
                            i += 2
                            while (i < text.length && depth > 0) {
                                when (text[i]) {
                                    '{' -> depth++
                                    '}' -> depth--
                                    '"' -> i = stringEnd(i) - 1
                                }
                                i++
                            }
                        }
                        else -> i++
                    }
                }
                return text.length
            }
            var i = 0
            while (i < text.length) {
                when {
                    text.startsWith("//", i) -> while (i < text.length && text[i] != '\n') i++
                    text.startsWith("/*", i) -> {
                        val end = text.indexOf("*/", i + 2).let { if (it < 0) text.length else it + 2 }
                        keepLines(i, end)
                        i = end
                    }
                    text[i] == '"' -> {
                        val end = stringEnd(i)
                        out.append("\"\"")
                        keepLines(i, end)
                        i = end
                    }
                    text[i] == '\'' && i + 2 < text.length && (text[i + 2] == '\'' || text[i + 1] == '\\') -> {
                        i = text.indexOf('\'', i + 2) + 1
                        out.append("' '")
                    }
                    else -> out.append(text[i++])
                }
            }
            return out.toString()
        }
    }
}
