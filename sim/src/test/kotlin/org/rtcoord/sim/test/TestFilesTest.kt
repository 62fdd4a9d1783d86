package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir

/** Test files are found at any depth and named so that no two reports of a run collide. */
class TestFilesTest {
    private fun touch(directory: Path, name: String): Path =
        directory.resolve(name).also {
            Files.createDirectories(it.parent)
            Files.writeString(it, "")
        }

    @Test
    fun `a directory's test files are named by their paths below it, build output and hidden directories skipped`(
        @TempDir directory: Path
    ) {
        listOf(
                "a/transient.test.kts",
                "b/transient.test.kts",
                "top.test.kts",
                "target/copy.test.kts",
                ".hidden/x.test.kts",
                "notes.kts",
            )
            .forEach { touch(directory, it) }
        assertEquals(listOf("a/transient", "b/transient", "top"), TestFiles.find(listOf(directory)).map { it.name })
    }

    @Test
    fun `files given by themselves are named by their file names, or by as much of their paths as tells them apart`(
        @TempDir directory: Path
    ) {
        val a = touch(directory, "x/a/transient.test.kts")
        val b = touch(directory, "x/b/transient.test.kts")
        val c = touch(directory, "y/a/transient.test.kts")
        val single = touch(directory, "y/single.test.kts")
        assertEquals(
            listOf("x/a/transient", "x/b/transient", "y/a/transient", "single"),
            TestFiles.find(listOf(a, b, c, single)).map { it.name },
        )
        assertEquals(listOf("a/transient", "b/transient"), TestFiles.find(listOf(a, b)).map { it.name })
        assertEquals(listOf("transient"), TestFiles.find(listOf(a, a)).map { it.name }, "a file given twice runs once")
    }
}
