package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.nio.file.attribute.FileTime
import java.nio.file.attribute.PosixFilePermissions
import java.util.concurrent.CompletableFuture
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.api.io.TempDir

/**
 * The packaged command end to end: `java -jar` on the built jar in a process of its own, and the `./rtcoord` launcher
 * that builds it when needed.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class CliJarIT {
    private val localisation = Localisation()
    private val jar: Path = Paths.get(System.getProperty("rtcoord.cli.jar"))
    private val root: Path = Paths.get(System.getProperty("rtcoord.root"))

    @AfterAll fun stop() = localisation.close()

    /** What a process printed and how it ended. */
    data class Run(val status: Int, val stdout: String, val stderr: String, val millis: Long)

    private fun run(command: List<String>, path: String? = null, environment: Map<String, String> = emptyMap()): Run {
        val builder = ProcessBuilder(command)
        path?.let { builder.environment()["PATH"] = it }
        builder.environment().putAll(environment)
        builder.environment().remove("RTCTREE_NAMESERVERS")
        builder.environment().remove("RTCOORD_NAMESERVERS")
        val started = System.nanoTime()
        val process = builder.start()
        val stdout = process.inputStream.bufferedReader().readText()
        val stderr = process.errorStream.bufferedReader().readText()
        assertTrue(process.waitFor(60, TimeUnit.SECONDS), "${command.joinToString(" ")} did not end")
        return Run(process.exitValue(), stdout, stderr, (System.nanoTime() - started) / 1_000_000)
    }

    private fun rtcoord(vararg arguments: String) = run(listOf("java", "-jar", jar.toString()) + arguments)

    @Test
    fun `the jar lists the system like the command objects do, and exits promptly`() {
        val listed = rtcoord("ls", "-l", localisation.host)
        assertEquals(Run(0, runRtcoord("ls", "-l", localisation.host).ok(), "", listed.millis), listed)
        println("java -jar ... ls -l took ${listed.millis} ms")
        assertTrue(listed.millis < 10_000, "took ${listed.millis} ms")
    }

    @Test
    fun `the jar's errors are one line with status 1, usage errors status 2`() {
        val missing = rtcoord("cat", localisation.path("sonar0.rtc"))
        assertEquals(Run(1, "", "rtcoord: ${localisation.path("sonar0.rtc")}: not found\n", missing.millis), missing)
        val usage = rtcoord("ls", "--long")
        assertEquals(2, usage.status)
        assertTrue(usage.stderr.startsWith("Usage: rtcoord ls"), usage.stderr)
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
    fun `the jar exits promptly after watching, observers detached`() {
        val watched = rtcoord("watch", localisation.path("gyro0.rtc"), "--for", "1s")
        assertEquals(0, watched.status, watched.stderr)
        assertEquals(emptySet<String>(), localisation.system.component("gyro0").observerIds)
    }

    @Test
    fun `run stopped by SIGTERM stops cleanly with status 0, observers detached, every time`(@TempDir directory: Path) {
        val script =
            directory.resolve("restart.coord.kts").also {
                Files.writeString(it, "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n")
            }
        val address = localisation.host.removePrefix("/").substringBefore('/')
        val outcomes =
            List(SIGTERM_ROUNDS) {
                val process =
                    ProcessBuilder("java", "-jar", jar.toString(), "-n", address, "run", script.toString()).start()
                val stdout = LinkedBlockingQueue<String>()
                val reader = Thread {
                    process.inputStream.bufferedReader().forEachLine { stdout += it }
                }
                    .apply { start() }
                val stderr = CompletableFuture.supplyAsync { process.errorStream.bufferedReader().readText() }
                val printed = mutableListOf<String>()
                while (printed.none { "coordinating:" in it }) {
                    printed += stdout.poll(120, TimeUnit.SECONDS) ?: break
                }
                // Not Process.destroy, which sends SIGTERM but closes the streams this test still reads.
                assertEquals(
                    0,
                    ProcessBuilder("kill", "-TERM", process.pid().toString()).start().waitFor(),
                    "kill -TERM",
                )
                assertTrue(process.waitFor(60, TimeUnit.SECONDS), "run did not end after SIGTERM")
                reader.join()
                printed += generateSequence { stdout.poll() }
                Run(process.exitValue(), printed.joinToString("\n"), stderr.get(), 0)
            }
        val unclean = outcomes.filter {
            it.status != 0 ||
                it.stderr.isNotEmpty() ||
                it.stdout.lines().none { line ->
                    line.endsWith("stopped by SIGTERM; 0 handler failures; 0 failed actions")
                }
        }
        assertEquals(emptyList<Run>(), unclean, "of $SIGTERM_ROUNDS runs stopped by SIGTERM")
        assertEquals(emptySet<String>(), localisation.system.component("gyro0").observerIds)
    }

    @Test
    fun `the launcher runs the jar as it is when nothing changed`(@TempDir directory: Path) {
        val tree = launcherTree(directory)
        val version = run(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory))
        assertEquals(
            Run(
                0,
                "rtcoord ${jar.fileName.toString().removePrefix("rtcoord-cli-").removeSuffix(".jar")}\n",
                "",
                version.millis,
            ),
            version,
        )
        assertTrue(Files.notExists(directory.resolve("maven-called")))
    }

    @Test
    fun `the launcher builds first, saying so in one line, when a source is newer than the jar`(
        @TempDir directory: Path
    ) {
        val tree = launcherTree(directory)
        val source = Files.createDirectories(tree.resolve("core/src")).resolve("Changed.kt")
        Files.writeString(source, "")
        Files.setLastModifiedTime(source, FileTime.fromMillis(System.currentTimeMillis() + 60_000))
        val version = run(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory))
        assertEquals(0, version.status, version.stderr)
        assertEquals("rtcoord: building (first run)...\n", version.stderr)
        assertEquals(
            "-B -ntp -q -Dstyle.color=never install -DskipTests -Drtcoord.dist.skip -pl cli -am\n",
            Files.readString(directory.resolve("maven-called")),
        )
    }

    @Test
    fun `a link to the launcher from elsewhere runs the checkout it points into`(@TempDir directory: Path) {
        val tree = launcherTree(directory)
        val link = Files.createDirectories(directory.resolve("home/bin")).resolve("rtcoord")
        Files.createSymbolicLink(link, tree.resolve("rtcoord"))
        val version = run(listOf(link.toString(), "--version"), fakeMaven(directory))
        assertEquals(Run(0, "rtcoord ${version()}\n", "", version.millis), version)
        assertTrue(Files.notExists(directory.resolve("maven-called")))
    }

    @Test
    fun `the launcher builds when there is no jar`(@TempDir directory: Path) {
        val tree = launcherTree(directory)
        Files.delete(tree.resolve("cli/target").resolve(jar.fileName))
        val version = run(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory))
        assertEquals(0, version.status, version.stderr)
        assertEquals("rtcoord: building (first run)...\n", version.stderr)
    }

    @Test
    fun `the launcher archives a browsing command's classes on its first run and maps them after, silently`(
        @TempDir directory: Path
    ) {
        val tree = launcherTree(directory)
        // Sources and jar made a while ago, so that an archive made now is newer than all of them.
        Files.walk(tree)
            .filter { Files.isRegularFile(it) }
            .forEach { Files.setLastModifiedTime(it, FileTime.fromMillis(System.currentTimeMillis() - 600_000)) }
        Files.setLastModifiedTime(
            tree.resolve("cli/target").resolve(jar.fileName),
            FileTime.fromMillis(System.currentTimeMillis() - 300_000),
        )
        val cache = directory.resolve("cache")
        val environment = mapOf("RTCOORD_CACHE" to cache.toString())
        val expected = runRtcoord("ls", "-l", localisation.host).ok()
        fun listing() =
            run(
                listOf(tree.resolve("rtcoord").toString(), "ls", "-l", localisation.host),
                fakeMaven(directory),
                environment,
            )

        assertEquals(
            Run(0, "rtcoord ${version()}\n", "", 0),
            run(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory), environment)
                .copy(millis = 0),
        )
        assertTrue(Files.notExists(cache.resolve("cds")), "--version makes no archive")
        assertEquals(
            0,
            run(listOf(tree.resolve("rtcoord").toString(), "ls", "--help"), fakeMaven(directory), environment).status,
        )
        assertTrue(Files.notExists(cache.resolve("cds")), "a help screen makes no archive")
        assertEquals(Run(0, expected, "", 0), listing().copy(millis = 0))
        val archive = Files.list(cache.resolve("cds")).use { files -> files.toList() }.single()
        assertTrue(archive.fileName.toString().startsWith("browse"), archive.toString())
        val made = Files.getLastModifiedTime(archive)
        assertEquals(Run(0, expected, "", 0), listing().copy(millis = 0))
        assertEquals(made, Files.getLastModifiedTime(archive), "the archive is mapped, not made again")
        // Other commands map it too, silently, and never make it again.
        assertEquals(
            Run(0, "rtcoord ${version()}\n", "", 0),
            run(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory), environment)
                .copy(millis = 0),
        )
        assertEquals(made, Files.getLastModifiedTime(archive), "--version maps the archive")

        // An archive the JVM cannot use is ignored without a word.
        Files.delete(archive)
        Files.writeString(archive, "not an archive")
        assertEquals(Run(0, expected, "", 0), listing().copy(millis = 0))
        assertTrue(Files.notExists(directory.resolve("maven-called")))
    }

    private fun version() = jar.fileName.toString().removePrefix("rtcoord-cli-").removeSuffix(".jar")

    /**
     * A copy of the project as the launcher sees it: the script, module folders, and the built jar with its lib folder,
     * so the launcher can be tried without touching the real build.
     */
    private fun launcherTree(directory: Path): Path {
        val tree = Files.createDirectories(directory.resolve("project"))
        Files.copy(root.resolve("rtcoord"), tree.resolve("rtcoord"))
        val launcher = Files.createDirectories(tree.resolve("cli/src/dist/bin")).resolve("rtcoord")
        Files.copy(root.resolve("cli/src/dist/bin/rtcoord"), launcher)
        Files.writeString(tree.resolve("pom.xml"), "")
        listOf("idl", "datatypes", "runtime", "core", "dsl", "sim", "examples").forEach {
            Files.createDirectories(tree.resolve(it))
        }
        Files.writeString(tree.resolve("examples/localisation.coord.kts"), "")
        val target = Files.createDirectories(tree.resolve("cli/target"))
        Files.createSymbolicLink(target.resolve("lib"), jar.resolveSibling("lib"))
        Files.copy(jar, target.resolve(jar.fileName))
        // The copy is the newest file of the tree, as a jar just built is.
        Files.setLastModifiedTime(
            target.resolve(jar.fileName),
            FileTime.fromMillis(System.currentTimeMillis() + 30_000),
        )
        return tree
    }

    /** A PATH whose `mvn` records its arguments and "builds" by copying the real jar into place. */
    private fun fakeMaven(directory: Path): String {
        val bin = Files.createDirectories(directory.resolve("bin"))
        val mvn = bin.resolve("mvn")
        val built = directory.resolve("project/cli/target").resolve(jar.fileName)
        Files.writeString(
            mvn,
            "#!/bin/sh\necho \"$@\" > '${directory.resolve("maven-called")}'\ncp '$jar' '$built'\ntouch -d '+2 minutes' '$built'\n",
        )
        Files.setPosixFilePermissions(mvn, PosixFilePermissions.fromString("rwxr-xr-x"))
        return "$bin:${System.getenv("PATH")}"
    }
}

/** How many times the SIGTERM test stops `run`: the failure it guards against came in about one stop of three. */
private const val SIGTERM_ROUNDS = 6
