package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.BeforeAll
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.api.io.TempDir

/**
 * The distribution archive as a user gets it: unpacked in a folder of its own, far from the source tree and the build,
 * and run with nothing but a JDK on the PATH.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class DistributionIT {
    private val localisation = Localisation()
    private val jar: Path = Paths.get(System.getProperty("rtcoord.cli.jar"))
    private val version = jar.fileName.toString().removePrefix("rtcoord-cli-").removeSuffix(".jar")

    private lateinit var directory: Path
    private lateinit var home: Path

    @BeforeAll
    fun unpack(@TempDir unpacked: Path) {
        directory = unpacked
        val archive = jar.resolveSibling("rtcoord-$version.tar.gz")
        assertTrue(Files.isRegularFile(archive), "$archive was built")
        assertEquals(0, run(listOf("tar", "-xzf", archive.toString(), "-C", directory.toString())).status)
        home = directory.resolve("rtcoord-$version")
    }

    @AfterAll fun stop() = localisation.close()

    private fun run(command: List<String>) =
        runProcess(command, environment = mapOf("RTCOORD_CACHE" to directory.resolve("cache").toString()))

    @Test
    fun `bin rtcoord runs from the unpacked archive and lists the system as the command objects do`() {
        assertEquals(
            ProcessRun(0, "rtcoord $version\n", ""),
            run(listOf(home.resolve("bin/rtcoord").toString(), "--version")),
        )
        val expected = runRtcoord("ls", "-l", localisation.host).ok()
        val rtcoord = home.resolve("bin/rtcoord").toString()
        assertEquals(ProcessRun(0, expected, ""), run(listOf(rtcoord, "ls", "-l", localisation.host)))
        assertEquals(
            ProcessRun(0, expected, ""),
            run(listOf(rtcoord, "ls", "-l", localisation.host)),
            "again, with the class archive mapped",
        )
    }

    @Test
    fun `bin rtcoord compiles with the compiler kept apart, and no other command has it on its class path`() {
        val rtcoord = home.resolve("bin/rtcoord").toString()
        val script = home.resolve("share/rtcoord/examples/localisation.coord.kts")
        val checked = run(listOf(rtcoord, "check", script.toString()))
        assertEquals(0, checked.status, checked.stderr)
        assertTrue(checked.stdout.startsWith("$script: compiles"), checked.stdout)
        val compiler = home.resolve("lib/compiler")
        assertTrue(
            Files.isRegularFile(compiler.resolve("kotlin-compiler-embeddable-${KotlinVersion.CURRENT}.jar")),
            "$compiler",
        )
        val manifest = java.util.jar.JarFile(home.resolve("lib/rtcoord-cli.jar").toFile()).use { it.manifest }
        val classPath = manifest.mainAttributes.getValue("Class-Path")
        assertTrue("kotlin-scripting-jvm-host" in classPath && "kotlin-compiler" !in classPath, classPath)
    }

    @Test
    fun `a link to bin rtcoord from elsewhere works`() {
        val link = Files.createDirectories(directory.resolve("user/bin")).resolve("rtcoord")
        Files.createSymbolicLink(link, home.resolve("bin/rtcoord"))
        assertEquals(ProcessRun(0, "rtcoord $version\n", ""), run(listOf(link.toString(), "--version")))
    }

    @Test
    fun `the archive carries the man page, completions and examples, and no test library`() {
        val man = Files.readString(home.resolve("share/man/man1/rtcoord.1"))
        assertTrue(man.startsWith(".TH RTCOORD 1 "), man.take(80))
        for (command in SUBCOMMANDS.keys) assertTrue(""".SS "rtcoord $command"""" in man, "the man page has $command")
        assertTrue(""".SS "rtcoord conf set"""" in man, "and subcommands")
        assertEquals(
            runRtcoord("completion", "bash").ok(),
            Files.readString(home.resolve("share/bash-completion/completions/rtcoord")),
        )
        assertEquals(
            runRtcoord("completion", "zsh").ok(),
            Files.readString(home.resolve("share/zsh/site-functions/_rtcoord")),
        )
        assertTrue(Files.isRegularFile(home.resolve("share/rtcoord/examples/localisation.coord.kts")))
        assertTrue(Files.isRegularFile(home.resolve("share/rtcoord/examples/rtcoord-coordinator.service")))
        val libraries = Files.list(home.resolve("lib")).use { files -> files.map { it.fileName.toString() }.toList() }
        assertTrue("rtcoord-cli.jar" in libraries, libraries.toString())
        assertEquals(
            emptyList<String>(),
            libraries.filter { it.startsWith("junit") || it.startsWith("opentest4j") || it.startsWith("apiguardian") },
        )
    }
}
