package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/** Test scripts compile once: the jar a host compiled serves every later host until the script changes. */
class TestScriptHostTest {
    @Test
    fun `an unchanged test script is not compiled again, even by a new host`(@TempDir directory: Path): Unit =
        runBlocking {
            val cache = directory.resolve("cache")
            val file = directory.resolve("cached.test.kts")
            Files.writeString(file, "system(\"a.xml\")\ncoordinator(\"a.coord.kts\")\nexpectLog(\"started\")\n")
            assertEquals(1, TestScriptHost(cache).load(file).steps.size)
            val cached = Files.list(cache).use { it.toList() }.single()
            val compiledAt = Files.getLastModifiedTime(cached)

            assertEquals(1, TestScriptHost(cache).load(file).steps.size, "the cached test declares the same steps")
            assertEquals(listOf(cached), Files.list(cache).use { it.toList() })
            assertEquals(compiledAt, Files.getLastModifiedTime(cached), "the cached jar was not rewritten")

            Files.writeString(file, Files.readString(file) + "expectLog(\"stopped\")\n")
            assertEquals(2, TestScriptHost(cache).load(file).steps.size)
            assertEquals(2, Files.list(cache).use { it.count() }, "a changed test compiles anew")
        }
}
