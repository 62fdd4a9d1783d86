package org.rtcoord.sim.test

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import kotlin.io.path.name

/**
 * Finds the test files of a run and names them: a directory's `*.test.kts` files at any depth (build output, `target`,
 * and hidden directories skipped), each named by its path relative to that directory; a file given by itself, by its
 * file name. Files of one name are named by as many of the last parts of their paths as tell them apart (`a/transient`,
 * `b/transient`), so that no two reports collide; a file given twice runs once.
 */
internal object TestFiles {
    private const val SUFFIX = ".test.kts"

    fun find(paths: List<Path>): List<TestFile> {
        val found =
            paths
                .flatMap { path ->
                    require(Files.exists(path)) { "$path: no such file or directory" }
                    if (Files.isDirectory(path)) inDirectory(path).map { it to path.relativize(it) }
                    else listOf(path to path.fileName)
                }
                .distinctBy { (file, _) -> file.toRealPath() }
        val names = found.map { (_, relative) -> nameOf(relative) }
        val unique = names.toMutableList()
        for (clash in names.indices.groupBy { names[it] }.values.filter { it.size > 1 }) {
            val paths = clash.map { found[it].first.toAbsolutePath().normalize() }
            // The fewest trailing parts of their paths that tell them apart: a/transient, b/transient.
            val parts =
                (2..paths.maxOf { it.nameCount }).firstOrNull { k ->
                    paths.map { suffix(it, k) }.toSet().size == paths.size
                } ?: paths.maxOf { it.nameCount }
            clash.forEachIndexed { i, index -> unique[index] = nameOf(suffix(paths[i], parts)) }
        }
        val seen = HashMap<String, Int>()
        return found.mapIndexed { i, (file, _) ->
            val times = seen.merge(unique[i], 1, Int::plus)!!
            TestFile(file, if (times == 1) unique[i] else "${unique[i]} ($times)")
        }
    }

    private fun inDirectory(directory: Path): List<Path> =
        Files.walk(directory).use { walk ->
            walk
                .filter { it.name.endsWith(SUFFIX) && Files.isRegularFile(it) && !skipped(directory.relativize(it)) }
                .sorted()
                .toList()
        }

    private fun skipped(relative: Path): Boolean =
        (0 until relative.nameCount - 1).any {
            val part = relative.getName(it).toString()
            part == "target" || part.startsWith(".")
        }

    private fun nameOf(relative: Path): String =
        relative.toString().replace('\\', '/').removePrefix("/").removeSuffix(SUFFIX)

    private fun suffix(path: Path, parts: Int): Path =
        path.subpath((path.nameCount - parts).coerceAtLeast(0), path.nameCount)

    /** [path] relative to the working directory when it is below it, else absolute. */
    fun shown(path: Path): Path {
        val absolute = path.toAbsolutePath().normalize()
        val here = Paths.get("").toAbsolutePath()
        return if (absolute.startsWith(here)) here.relativize(absolute) else absolute
    }
}
