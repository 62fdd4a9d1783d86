package org.rtcoord.bench

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.jar.JarEntry
import java.util.jar.JarFile
import java.util.jar.JarOutputStream
import kotlinx.coroutines.runBlocking
import org.rtcoord.DirectoryNode
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.CompiledCoordinator
import org.rtcoord.fixtures.FixtureProcess

/**
 * Start-up of the command line as users run it (`./rtcoord`, whole processes, against the localisation system in a
 * fixture JVM): the bare JVM, `--version`, `--help`, a recursive listing, a coordinator started from a warm script
 * cache, and one compiled ahead of time (as a process, and loaded and started in a warm JVM, as a plug-in does). Then
 * where a browsing command's time goes, from a probe run in a fresh JVM on the CLI's class path as the launcher runs
 * one: the JVM's start, the command line, creating the tree, the first call (the ORB starts there), the rest of the
 * listing, closing and the JVM's exit.
 */
internal class StartupBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    private val javaCommand = Paths.get(System.getProperty("java.home"), "bin", "java").toString()

    suspend fun run() {
        report.section(
            "start-up, whole processes (${options.startupRepetitions} runs each after ${options.processWarmups} warm-up; localisation system in a fixture JVM)"
        )
        val missing = installation.cliMissing
        if (missing != null) {
            report.skipped("rtcoord", missing)
            return
        }
        FixtureProcess.start().use { fixtures ->
            commands(fixtures.address)
            script(fixtures.address)
            compiled(fixtures.address)
            report.section(
                "start-up breakdown: a probe on the CLI's class path, in a fresh JVM with the launcher's flags and an archive of its own"
            )
            breakdown(fixtures.address)
        }
    }

    private fun commands(address: String) {
        val launcher = installation.launcher.toString()
        val root = installation.root
        val jvm = TimedCommand("java -version (the JVM alone)", listOf(javaCommand) + JVM_FLAGS + "-version", root)
        val version = TimedCommand("rtcoord --version", listOf(launcher, "--version"), root)
        val commands =
            listOf(
                jvm,
                version,
                TimedCommand("rtcoord --help", listOf(launcher, "--help"), root),
                TimedCommand("rtcoord ls -l -R", listOf(launcher, "ls", "-l", "-R", "/$address/"), root),
            ) +
                listOfNotNull(
                    installation.peer("rtls")?.let {
                        TimedCommand("rtls -l -R", listOf(it.toString(), "-l", "-R", "/$address/"), root)
                    }
                )
        val times = commands.zip(timeInterleaved(commands, options.processWarmups, options.startupRepetitions))
        val bare = times.first().second
        for ((command, samples) in times) {
            val notes =
                when (command) {
                    jvm -> "launcher's flags: ${JVM_FLAGS.joinToString(" ")}"
                    else ->
                        if (command.label.startsWith("rtcoord"))
                            "%+.0f ms over the bare JVM".format((samples.median - bare.median) * 1000)
                        else ""
                }
            report.row(command.label, samples, notes)
        }
        val ls = times.first { it.first.label == "rtcoord ls -l -R" }.second
        times
            .firstOrNull { it.first.label == "rtls -l -R" }
            ?.let { (_, rtls) ->
                report.note(
                    "start-up: rtcoord ls -l -R is ${speedup(ls, rtls, "rtls")} on the 4-component localisation system; target: no slower than 1.2x"
                )
            }
    }

    /** `rtcoord run` from a warm script cache: the first run compiles and fills it, the timed ones do not. */
    private fun script(address: String) {
        if (!options.scripts) {
            report.skipped(RUN_CACHED, "coordinator scripts are not compiled in a ${options.profile} run")
            return
        }
        val cache = Files.createTempDirectory("bench-cache")
        try {
            val script = installation.root.resolve("examples/localisation.coord.kts").toString()
            val command =
                TimedCommand(
                    RUN_CACHED,
                    listOf(installation.launcher.toString(), "-n", address, "run", "--for", "1ms", script),
                    installation.root,
                    environment = mapOf("XDG_CACHE_HOME" to cache.toString()),
                )
            val first = command.run()
            report.value("rtcoord run, first time (compiles the script)", first.nanos / 1e9, "s", "into an empty cache")
            report.row(
                RUN_CACHED,
                timeInterleaved(listOf(command), options.processWarmups, options.startupRepetitions).single(),
                "coordinator started and stopped",
            )
        } finally {
            cache.toFile().deleteRecursively()
        }
    }

    /**
     * A coordinator compiled ahead of time (`rtcoord compile`): `rtcoord run NAME.jar` as a whole process, which
     * compiles nothing and reads no script cache; then, in this JVM once warm, what a plug-in waits for: the jar loaded
     * ([CompiledCoordinator.load], no compiler) and the coordinator started on a tree that has already listed the
     * system (its rule subscribed, its component watched).
     */
    private fun compiled(address: String) {
        if (!options.scripts) {
            report.skipped(RUN_COMPILED, "coordinator scripts are not compiled in a ${options.profile} run")
            return
        }
        val scratch = Files.createTempDirectory("bench-compiled")
        try {
            val jar = scratch.resolve("localisation.jar")
            val script = installation.root.resolve("examples/localisation.coord.kts").toString()
            TimedCommand(
                    "rtcoord compile",
                    listOf(installation.launcher.toString(), "compile", script, "-o", jar.toString()),
                    installation.root,
                )
                .run()
            val command =
                TimedCommand(
                    RUN_COMPILED,
                    listOf(installation.launcher.toString(), "-n", address, "run", "--for", "1ms", jar.toString()),
                    installation.root,
                )
            report.row(
                RUN_COMPILED,
                timeInterleaved(listOf(command), options.processWarmups, options.startupRepetitions).single(),
                "no compiler, no script cache",
            )
            val config = TreeConfig(listOf(address))
            RtcTree(config).use { tree ->
                runBlocking { (tree.node("/$address/") as DirectoryNode).survey() }
                val times =
                    (0 until WARM_LOADS + options.startupRepetitions)
                        .map {
                            val start = System.nanoTime()
                            Coordinator(tree, CompiledCoordinator.load(jar, emptyList(), config)).use { coordinator ->
                                runBlocking { coordinator.start() }
                            }
                            (System.nanoTime() - start) / 1e6
                        }
                        .drop(WARM_LOADS)
                report.row(
                    "compiled coordinator: load and start, warm JVM",
                    Samples(times, "ms"),
                    "CompiledCoordinator.load + Coordinator.start, as JavaCoordinator.load then start(); target: under 300 ms",
                )
            }
        } finally {
            scratch.toFile().deleteRecursively()
        }
    }

    /**
     * The probe runs as the launcher runs a browsing command: its flags, and a class-data sharing archive written by
     * the first (warm-up) run and mapped by the timed ones. CDS wants jars on the class path, so the probe's classes go
     * into one of their own.
     */
    private fun breakdown(address: String) {
        val scratch = Files.createTempDirectory("bench-probe")
        try {
            val classPath = listOf(installation.cliJar!!, probeJar(scratch)).joinToString(java.io.File.pathSeparator)
            val archive = scratch.resolve("probe.jsa")
            fun probe(vararg options: String) =
                listOf(javaCommand) +
                    JVM_FLAGS +
                    options +
                    listOf("-cp", classPath, StartupProbe::class.java.name, address)
            // The first run writes the archive and counts the classes a listing loads; the timed ones map it.
            val first =
                TimedCommand("startup probe", probe("-XX:ArchiveClassesAtExit=$archive") + "classes", installation.root)
                    .run()
            val classes = first.output.single { it.startsWith("classes ") }.substringAfter(' ').toDouble()
            val runs =
                List(options.startupRepetitions) {
                    val launched = System.currentTimeMillis()
                    val run =
                        TimedCommand("startup probe", probe("-XX:SharedArchiveFile=$archive"), installation.root).run()
                    val fields = run.output.single { it.startsWith("probe ") }.split(' ').drop(1).map { it.toLong() }
                    val entered = fields.first()
                    val ended = fields.last()
                    listOf((entered - launched).toDouble()) +
                        fields.subList(1, fields.size - 1).map { it / 1e6 } +
                        (launched + run.nanos / 1e6 - ended)
                }
            val rows =
                listOf(
                    "JVM start to main" to "process start, JVM init with the archive, loading the main class",
                    "command line made and parsed" to "Clikt: rtcoord and its ls subcommand, as the launcher runs them",
                    "RtcTree(config)" to "the tree and its scopes; the ORB starts at the first call",
                    "first call: list the name server" to "ORB init, connection, naming resolve and list",
                    "rest of ls -l -R: survey" to "every context, manager and component below, concurrently",
                    "tree closed" to "ORB shut down",
                    "JVM exit" to "from the end of main to the process's end",
                )
            rows.forEachIndexed { column, (label, notes) ->
                report.row(label, Samples(runs.map { it[column] }, "ms"), notes)
            }
            report.value(
                "classes a listing loads",
                classes,
                "classes",
                "in the run that wrote the archive; the timed runs map them",
            )
        } finally {
            scratch.toFile().deleteRecursively()
        }
    }

    /** A jar in [directory] holding the probe's classes, from this module's jar or classes directory. */
    private fun probeJar(directory: Path): Path {
        val source = Paths.get(StartupProbe::class.java.protectionDomain.codeSource.location.toURI())
        val jar = directory.resolve("probe.jar")
        val prefix = StartupProbe::class.java.name.replace('.', '/')
        JarOutputStream(Files.newOutputStream(jar)).use { out ->
            fun add(name: String, bytes: ByteArray) {
                out.putNextEntry(JarEntry(name))
                out.write(bytes)
                out.closeEntry()
            }
            if (Files.isDirectory(source)) {
                Files.walk(source).use { files ->
                    files
                        .filter { Files.isRegularFile(it) && source.relativize(it).toString().startsWith(prefix) }
                        .forEach { add(source.relativize(it).toString(), Files.readAllBytes(it)) }
                }
            } else {
                JarFile(source.toFile()).use { classes ->
                    classes
                        .entries()
                        .asSequence()
                        .filter { it.name.startsWith(prefix) }
                        .forEach { add(it.name, classes.getInputStream(it).readBytes()) }
                }
            }
        }
        return jar
    }

    private companion object {
        const val RUN_CACHED = "rtcoord run --for 1ms, cached script"
        const val RUN_COMPILED = "rtcoord run --for 1ms, compiled coordinator (jar)"

        /** Loads and starts before the timed ones: the JIT's first rounds are not what a warm plug-in sees. */
        const val WARM_LOADS = 5

        /** The flags `./rtcoord` starts the JVM of a browsing command with (cli/src/dist/bin/rtcoord). */
        val JVM_FLAGS =
            listOf(
                "-XX:TieredStopAtLevel=1",
                "-XX:+UseG1GC",
                "-Xshare:auto",
                "-XX:CICompilerCount=1",
                "-XX:-UsePerfData",
            )
    }
}
