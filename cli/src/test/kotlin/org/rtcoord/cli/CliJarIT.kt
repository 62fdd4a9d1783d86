package org.rtcoord.cli

import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.api.io.TempDir

/** The packaged command end to end: `java -jar` on the built jar in a process of its own. */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class CliJarIT {
    private val localisation = Localisation()
    private val jar: Path = Paths.get(System.getProperty("rtcoord.cli.jar"))

    @AfterAll fun stop() = localisation.close()

    private fun rtcoord(vararg arguments: String) = runProcess(listOf("java", "-jar", jar.toString()) + arguments)

    @Test
    fun `the jar lists the system like the command objects do, and exits promptly`() {
        val listed = rtcoord("ls", "-l", localisation.host)
        assertEquals(ProcessRun(0, runRtcoord("ls", "-l", localisation.host).ok(), ""), listed)
        println("java -jar ... ls -l took ${listed.millis} ms")
        assertTrue(listed.millis < 10_000, "took ${listed.millis} ms")
    }

    @Test
    fun `the jar's errors are one line with status 1, usage errors status 2`() {
        val missing = rtcoord("cat", localisation.path("sonar0.rtc"))
        assertEquals(ProcessRun(1, "", "rtcoord: ${localisation.path("sonar0.rtc")}: not found\n"), missing)
        val usage = rtcoord("ls", "--long")
        assertEquals(2, usage.status)
        assertTrue(usage.stderr.startsWith("Usage: rtcoord ls"), usage.stderr)
    }

    @Test
    fun `the jar has no compiler on its class path, and a command that compiles says how to run it`(
        @TempDir directory: Path
    ) {
        val script = Files.writeString(directory.resolve("a.coord.kts"), "after(0.seconds) { log(\"hi\") }\n")
        assertEquals(
            ProcessRun(
                1,
                "",
                "rtcoord: rtcoord check needs the Kotlin compiler, which bin/rtcoord adds to the class path: run it with " +
                    "bin/rtcoord (or java -cp with lib/compiler/*.jar added)\n",
            ),
            rtcoord("check", script.toString()),
        )
    }

    @Test
    fun `-v turns JacORB's logging on and adds the stack trace before the error line`() {
        // In a process of its own: logging is configured once per JVM.
        val failed = rtcoord("-v", "cat", localisation.path("sonar0.rtc"))
        assertEquals(1, failed.status)
        val lines = failed.stderr.trimEnd().lines()
        assertTrue(lines.any { it.startsWith("rtcoord: INFO org.jacorb.") }, failed.stderr)
        assertTrue(lines.any { it.startsWith("org.rtcoord.NotFoundException: ") }, failed.stderr)
        assertTrue(lines.any { it.trim().startsWith("at org.rtcoord.") }, failed.stderr)
        assertEquals("rtcoord: ${localisation.path("sonar0.rtc")}: not found", lines.last())
    }

    @Test
    fun `-v prints the script's frames of a failed handler under its line`(@TempDir directory: Path) {
        // In a process of its own, as -v's logging is configured once per JVM.
        val script =
            directory.resolve("parse.coord.kts").also {
                Files.writeString(it, "fun parse(text: String) = text.toInt()\nafter(0.seconds) { parse(\"three\") }\n")
            }
        val address = localisation.host.removePrefix("/").substringBefore('/')
        val ran = rtcoord("-v", "-n", address, "run", "--for", "2s", script.toString())
        assertEquals(0, ran.status, ran.stderr)
        val failed =
            """timer after 0s failed at parse\.coord\.kts:1: NumberFormatException: For input string: "three"\n"""
        assertTrue(
            Regex("""$failed    at parse\.coord\.kts:1 \(.+\)\n    at parse\.coord\.kts:2 \(.+\)\n""")
                .containsMatchIn(ran.stdout),
            ran.stdout,
        )
    }

    @Test
    fun `a cached coordinator starts without the scripting host and Kotlin's full reflection`(
        @TempDir directory: Path
    ) {
        // A text no other test compiles: the first run compiles it into the cache, the second starts it from there.
        val script =
            Files.writeString(
                directory.resolve("light.coord.kts"),
                "// ${System.nanoTime()}\nafter(0.seconds) { log(\"started\") }\n",
            )
        val address = localisation.host.removePrefix("/").substringBefore('/')
        val run = listOf("-n", address, "run", "--for", "1ms", script.toString())
        assertEquals(0, rtcoord(*run.toTypedArray()).status)
        val loaded = directory.resolve("classes.log")
        val cached = runProcess(listOf("java", "-Xlog:class+load:file=$loaded", "-jar", jar.toString()) + run)
        assertEquals(0, cached.status, cached.stderr)
        // The host's compiled scripts, and what full reflection reads a template's annotations into: once loaded, they
        // stay for as long as the coordinator runs, 800 classes and 13 MB of its 81 (bench/README.md).
        val heavy =
            Files.readAllLines(loaded).filter {
                "kotlin.reflect.jvm.internal.impl.descriptors." in it || "kotlin.script.experimental.jvm.impl." in it
            }
        assertEquals(emptyList<String>(), heavy.take(3))
    }

    @Test
    fun `the jar exits promptly after watching, observers detached`() {
        val watched = rtcoord("watch", localisation.path("gyro0.rtc"), "--for", "1s")
        assertEquals(0, watched.status, watched.stderr)
        assertEquals(emptySet<String>(), localisation.system.component("gyro0").observerIds)
    }

    /**
     * `--for` is kept by the command's own event loop: a `withTimeout` there started kotlinx's shared timer thread,
     * which lived as long as the command. The process's threads are read from Linux's /proc while it watches.
     */
    @Test
    fun `watch --for starts no thread to keep its time`() {
        val process =
            ProcessBuilder("java", "-jar", jar.toString(), "watch", localisation.path("gyro0.rtc"), "--for", "2s")
                .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .redirectError(ProcessBuilder.Redirect.DISCARD)
                .start()
        val seen = mutableSetOf<String>()
        while (!process.waitFor(20, TimeUnit.MILLISECONDS)) seen += threadNames(process.pid())
        assertEquals(0, process.exitValue())
        // Seen while the tree was up, that is while the command waited for its time.
        assertTrue(seen.any { it.startsWith("rtcoord-tree") }, "threads seen: $seen")
        // Linux keeps 15 characters of a thread's name: kotlinx.coroutines.DefaultExecutor is "kotlinx.corouti".
        assertEquals(emptyList<String>(), seen.filter { it.startsWith("kotlinx.corouti") }, "threads seen: $seen")
    }

    /**
     * `rtcoord print PORT | head -3`: once the reader has its lines and leaves, the command ends. The JVM ignores
     * SIGPIPE, and before, `print` went on writing to the closed pipe until killed.
     */
    @Test
    fun `print ends with status 0 once its output has no reader`() {
        val process =
            ProcessBuilder("java", "-jar", jar.toString(), "print", localisation.path("laser0.rtc:laser"))
                .redirectError(ProcessBuilder.Redirect.DISCARD)
                .start()
        try {
            val output = process.inputStream.bufferedReader()
            repeat(3) { assertTrue(output.readLine()?.contains("TimedDoubleSeq") == true, "a sample line") }
            output.close()
            assertTrue(process.waitFor(30, TimeUnit.SECONDS), "print still running after its reader left")
            assertEquals(0, process.exitValue())
        } finally {
            process.destroyForcibly()
        }
    }

    /** The names of [pid]'s threads now; none once it has ended. */
    private fun threadNames(pid: Long): Set<String> =
        try {
            Files.list(Paths.get("/proc", "$pid", "task")).use { tasks ->
                tasks
                    .toList()
                    .mapNotNull { runCatching { Files.readString(it.resolve("comm")).trim() }.getOrNull() }
                    .toSet()
            }
        } catch (e: IOException) {
            emptySet()
        }
}
