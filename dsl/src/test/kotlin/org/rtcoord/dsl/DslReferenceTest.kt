package org.rtcoord.dsl

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.ApiDump
import org.rtcoord.dsl.script.ScriptHost

/**
 * `docs/dsl.md`, the language's reference, against the language: every example in it compiles and evaluates as a
 * coordinator script, and every public declaration of the language is named in it.
 */
class DslReferenceTest {
    private val reference = Paths.get("..", "docs", "dsl.md")
    private val text = Files.readString(reference)

    @TempDir lateinit var directory: Path

    @Test
    fun `every example of the reference compiles and evaluates as a script`(): Unit = runBlocking {
        val examples =
            Regex("```kotlin\n(.*?)```", RegexOption.DOT_MATCHES_ALL).findAll(text).map { it.groupValues[1] }.toList()
        assertTrue(examples.size >= 8, "the reference has examples: ${examples.size}")
        val host = ScriptHost(directory.resolve("cache"))
        val failures = examples.mapIndexedNotNull { index, example ->
            val script = directory.resolve("example-${index + 1}.coord.kts")
            Files.writeString(script, example)
            runCatching { host.load(script) }
                .exceptionOrNull()
                ?.let { "example ${index + 1}:\n$example\n-> ${it.message}" }
        }
        assertEquals(emptyList<String>(), failures)
    }

    @Test
    fun `every public declaration of the language is named in the reference`() {
        val sources = Paths.get("src", "main", "kotlin", "org", "rtcoord", "dsl")
        val declaration =
            Regex(
                """^\s*public (?:(?:suspend|infix|inline|open|data|enum|abstract|sealed|override|operator) )*(?:fun|val|var|class|object|typealias) (?:<[^>]*> )?(?:\w+\.)?(\w+)""",
                RegexOption.MULTILINE,
            )
        val names =
            Files.list(sources)
                .use { files ->
                    files
                        .filter { it.toString().endsWith(".kt") }
                        .toList()
                        .flatMap { file ->
                            declaration.findAll(Files.readString(file)).map { it.groupValues[1] }.toList()
                        }
                }
                .toSortedSet()
        assertTrue(names.size > 100, "found the declarations: ${names.size}")
        val missing = names.filterNot { Regex("""\b${Regex.escape(it)}\b""").containsMatchIn(text) }
        assertEquals(emptyList<String>(), missing, "public declarations that docs/dsl.md does not name")
    }

    /**
     * What the reference says Java calls (`` `getBackoff()` from Java ``) is a method of the dsl's API; before, it
     * named `backoffDuration`, which Java never sees.
     */
    @Test
    fun `every name the reference gives Java callers is a method Java can call`() {
        val named = Regex("""`(\w+)(?:\(\))?` from Java""").findAll(text).map { it.groupValues[1] }.toList()
        assertTrue(named.isNotEmpty(), "the reference names nothing for Java callers")
        val methods =
            ApiDump.publicClasses(Coordinator::class.java)
                .flatMap { ApiDump.visibleMethods(it) }
                .map { it.name }
                .toSet()
        assertEquals(
            emptyList<String>(),
            named.filterNot { it in methods },
            "names docs/dsl.md gives Java callers that no public method of the dsl has",
        )
    }
}
