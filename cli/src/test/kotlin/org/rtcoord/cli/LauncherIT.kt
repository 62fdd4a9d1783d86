package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.nio.file.attribute.FileTime
import java.nio.file.attribute.PosixFilePermissions
import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.api.io.TempDir

/**
 * The `./rtcoord` launcher of a checkout: it runs the built jar as it is, builds it first when a source is newer or it
 * is missing, and keeps class archives: one for browsing commands, one for each lasting command. A class apart from
 * [CliJarIT], so that the build's two test JVMs run them side by side.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class LauncherIT {
    private val localisation = Localisation()
    private val jar: Path = Paths.get(System.getProperty("rtcoord.cli.jar"))
    private val root: Path = Paths.get(System.getProperty("rtcoord.root"))

    @AfterAll fun stop() = localisation.close()

    @Test
    fun `the launcher runs the jar as it is when nothing changed`(@TempDir directory: Path) {
        val tree = launcherTree(directory)
        val version = runProcess(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory))
        assertEquals(ProcessRun(0, "rtcoord ${version()}\n", ""), version)
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
        val version = runProcess(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory))
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
        val version = runProcess(listOf(link.toString(), "--version"), fakeMaven(directory))
        assertEquals(ProcessRun(0, "rtcoord ${version()}\n", ""), version)
        assertTrue(Files.notExists(directory.resolve("maven-called")))
    }

    @Test
    fun `the launcher builds when there is no jar`(@TempDir directory: Path) {
        val tree = launcherTree(directory)
        Files.delete(tree.resolve("cli/target").resolve(jar.fileName))
        val version = runProcess(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory))
        assertEquals(0, version.status, version.stderr)
        assertEquals("rtcoord: building (first run)...\n", version.stderr)
    }

    @Test
    fun `the launcher archives a browsing command's classes on its first run and maps them after, silently`(
        @TempDir directory: Path
    ) {
        val tree = agedLauncherTree(directory)
        val cache = directory.resolve("cache")
        val environment = mapOf("RTCOORD_CACHE" to cache.toString())
        val expected = runRtcoord("ls", "-l", localisation.host).ok()
        fun listing() =
            runProcess(
                listOf(tree.resolve("rtcoord").toString(), "ls", "-l", localisation.host),
                fakeMaven(directory),
                environment,
            )

        assertEquals(
            ProcessRun(0, "rtcoord ${version()}\n", ""),
            runProcess(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory), environment),
        )
        assertTrue(Files.notExists(cache.resolve("cds")), "--version makes no archive")
        assertEquals(
            0,
            runProcess(listOf(tree.resolve("rtcoord").toString(), "ls", "--help"), fakeMaven(directory), environment)
                .status,
        )
        assertTrue(Files.notExists(cache.resolve("cds")), "a help screen makes no archive")
        assertEquals(ProcessRun(0, expected, ""), listing())
        val archive = Files.list(cache.resolve("cds")).use { files -> files.toList() }.single()
        assertTrue(archive.fileName.toString().startsWith("browse"), archive.toString())
        val made = Files.getLastModifiedTime(archive)
        assertEquals(ProcessRun(0, expected, ""), listing())
        assertEquals(made, Files.getLastModifiedTime(archive), "the archive is mapped, not made again")
        // Other commands map it too, silently, and never make it again.
        assertEquals(
            ProcessRun(0, "rtcoord ${version()}\n", ""),
            runProcess(listOf(tree.resolve("rtcoord").toString(), "--version"), fakeMaven(directory), environment),
        )
        assertEquals(made, Files.getLastModifiedTime(archive), "--version maps the archive")

        // An archive the JVM cannot use is ignored without a word.
        Files.delete(archive)
        Files.writeString(archive, "not an archive")
        assertEquals(ProcessRun(0, expected, ""), listing())
        assertTrue(Files.notExists(directory.resolve("maven-called")))
    }

    @Test
    fun `a lasting command archives the classes of its first run once it ends well, and maps only that archive after`(
        @TempDir directory: Path
    ) {
        val tree = agedLauncherTree(directory)
        val cache = directory.resolve("cache")
        val loaded = directory.resolve("loaded.txt")
        fun watch(vararg options: String, logged: Boolean = false) =
            runProcess(
                listOf(tree.resolve("rtcoord").toString(), "watch", *options, localisation.host),
                fakeMaven(directory),
                mapOf("RTCOORD_CACHE" to cache.toString()) +
                    if (logged) mapOf("RTCOORD_JAVA_OPTIONS" to "-Xlog:class+load:file=$loaded") else emptyMap(),
            )
        fun archives() = if (Files.notExists(cache.resolve("cds"))) emptyList() else archivesIn(cache)

        assertEquals(2, watch("--for", "soon").status)
        assertEquals(emptyList<String>(), archives(), "a command that failed makes no archive")
        assertEquals(0, watch("--for", "1s").status)
        val archive = archives().single()
        assertTrue(archive.startsWith("watch") && archive.endsWith(".jsa"), "its own archive, whole: $archive")
        val made = Files.getLastModifiedTime(cache.resolve("cds").resolve(archive))

        assertEquals(0, watch("--for", "1s", logged = true).status)
        assertEquals(listOf(archive), archives())
        assertEquals(made, Files.getLastModifiedTime(cache.resolve("cds").resolve(archive)), "mapped, not made again")
        // The command's classes and the JDK's come from that archive alone: no JDK archive is mapped beneath it.
        val sources =
            Files.readAllLines(loaded).associate { it.substringAfter("] ").substringBefore(" source: ") to it }
        assertTrue("source: shared objects file" in sources.getValue("org.rtcoord.cli.WatchCommand"), "archived")
        assertTrue(sources.values.none { "shared objects file (top)" in it }, "one archive, not two layers")
        assertTrue(Files.notExists(directory.resolve("maven-called")))
    }

    @Test
    fun `a SIGTERM to the launcher while it archives ends the command's JVM and leaves no partial archive`(
        @TempDir directory: Path
    ) {
        val tree = agedLauncherTree(directory)
        val cache = directory.resolve("cache")
        val watch =
            ProcessBuilder(tree.resolve("rtcoord").toString(), "watch", localisation.host)
                .redirectErrorStream(true)
                .apply {
                    environment()["PATH"] = fakeMaven(directory)
                    environment()["RTCOORD_CACHE"] = cache.toString()
                }
                .start()
        var jvm: ProcessHandle? = null
        try {
            // The JVM runs as the launcher's child while it writes the archive; it watches once it prints a line.
            val firstLine = CompletableFuture.supplyAsync { watch.inputStream.bufferedReader().readLine() }
            assertTrue(firstLine.get(60, TimeUnit.SECONDS) != null, "watch printed nothing")
            jvm = watch.toHandle().children().toList().single()
            watch.destroy()
            assertTrue(watch.waitFor(30, TimeUnit.SECONDS), "the launcher ended")
            assertTrue(!jvm.onExit().get(30, TimeUnit.SECONDS).isAlive, "the JVM ended with it")
            assertEquals(0, watch.exitValue(), "watch stops as on Ctrl-C")
            val archives = archivesIn(cache)
            assertTrue(archives.none { it.contains(".jsa.") }, "no partial archive left: $archives")
        } finally {
            // An orphaned JVM is no longer the launcher's descendant.
            jvm?.destroyForcibly()
            watch.destroyForcibly()
        }
    }

    @Test
    fun `a lasting command asks a JVM new enough to give freed native memory back, and an older one nothing`(
        @TempDir directory: Path
    ) {
        val launcher = launcherTree(directory).resolve("cli/src/dist/bin/rtcoord").toString()
        // The JVM on the PATH is a link, as /usr/bin/java is, to a JDK's bin/java, whose release file says its version.
        val jdk = Files.createDirectories(directory.resolve("jdk/bin")).parent
        val java = jdk.resolve("bin/java")
        val arguments = directory.resolve("java-called")
        Files.writeString(java, "#!/bin/sh\nprintf '%s\\n' \"$@\" > '$arguments'\n")
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"))
        val path = Files.createDirectories(directory.resolve("path"))
        Files.createSymbolicLink(path.resolve("java"), java)
        fun trims(javaVersion: String, vararg command: String): Boolean {
            Files.writeString(jdk.resolve("release"), "IMPLEMENTOR=\"Test\"\nJAVA_VERSION=\"$javaVersion\"\n")
            val run =
                runProcess(
                    listOf(launcher, *command),
                    "$path:${System.getenv("PATH")}",
                    mapOf("RTCOORD_CACHE" to directory.resolve("cache").toString()),
                )
            assertEquals(0, run.status, run.stderr)
            return "-XX:TrimNativeHeapInterval=10000" in Files.readAllLines(arguments)
        }

        assertTrue(trims("17.0.9", "run", "supervisor.coord.kts"), "17.0.9 has the option")
        assertTrue(trims("21.0.1", "watch", "/localhost"), "21.0.1 has it")
        assertTrue(trims("25", "run", "supervisor.coord.kts"), "every JVM from 22 on has it")
        assertTrue(!trims("17.0.8", "run", "supervisor.coord.kts"), "17.0.8 would refuse to start with it")
        assertTrue(!trims("21", "watch", "/localhost"), "21 would refuse to start with it")
        assertTrue(!trims("11.0.25", "run", "supervisor.coord.kts"), "11 would refuse to start with it")
        assertTrue(!trims("17.0.15", "ls", "/localhost"), "a command over in a moment has nothing to give back")
    }

    /** The names of the files in [cache]'s archive folder. */
    private fun archivesIn(cache: Path): List<String> =
        Files.list(cache.resolve("cds")).use { files -> files.map { it.fileName.toString() }.toList() }

    private fun version() = jar.fileName.toString().removePrefix("rtcoord-cli-").removeSuffix(".jar")

    /** [launcherTree] with its sources and jar made a while ago, so that an archive made now is newer than all. */
    private fun agedLauncherTree(directory: Path): Path {
        val tree = launcherTree(directory)
        Files.walk(tree)
            .filter { Files.isRegularFile(it) }
            .forEach { Files.setLastModifiedTime(it, FileTime.fromMillis(System.currentTimeMillis() - 600_000)) }
        Files.setLastModifiedTime(
            tree.resolve("cli/target").resolve(jar.fileName),
            FileTime.fromMillis(System.currentTimeMillis() - 300_000),
        )
        return tree
    }

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
