package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNotNull
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.dsl.script.ScriptHost

/**
 * A script compiled apart is in the cache, so the JVM that runs it next starts it without the compiler; one with errors
 * comes back with them, for that JVM has no compiler to find them with.
 */
class CompilerProcessTest {
    @Test
    fun `a script compiled in a JVM of its own is then taken from the cache`(@TempDir dir: Path) = runBlocking {
        // A text no other test compiles: it cannot be in the cache already.
        val script =
            Files.writeString(
                dir.resolve("apart.coord.kts"),
                "// ${System.nanoTime()}\non(component(\"laser0.rtc\")).state(ERROR) { log(\"laser down\") }\n",
            )
        val scripts = ScriptHost()
        assertFalse(scripts.isCached(script))
        assertNull(CompilerProcess.compile(script), "the other JVM compiled it")
        assertTrue(scripts.isCached(script))
    }

    @Test
    fun `a script with errors comes back with its problems, as check prints them`(@TempDir dir: Path) = runBlocking {
        val script = Files.writeString(dir.resolve("broken.coord.kts"), "on(nothing(${System.nanoTime()}))\n")
        val problems = CompilerProcess.compile(script)
        assertNotNull(problems)
        assertTrue(problems!!.any { it.startsWith("$script:1:") && "nothing" in it }, "$problems")
        assertFalse(ScriptHost().isCached(script))
    }

    @Test
    fun `the compiler's JVM gets this one's options but neither its class archive nor its list of classes`() {
        val launcher =
            listOf(
                "-XX:TieredStopAtLevel=1",
                "-XX:DumpLoadedClassList=/cache/cds/run.jsa.42.classes",
                "-XX:SharedArchiveFile=/cache/cds/browse.jsa",
                "-XX:ArchiveClassesAtExit=/cache/cds/browse.jsa.42",
                "-Drtcoord.compile=apart",
                "-XX:+UseSerialGC",
            )
        assertEquals(listOf("-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC"), CompilerProcess.compilerOptions(launcher))
    }
}
