package org.rtcoord.bench

import org.rtcoord.fixtures.FixtureProcess
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths

/**
 * Start-up of the command line as users run it (`./rtcoord`, whole processes, against the localisation
 * system in a fixture JVM): the bare JVM, `--version`, `--help`, a recursive listing, and a coordinator
 * started from a warm script cache. Then where a browsing command's time goes, from a probe run in a
 * fresh JVM on the CLI's class path: the JVM's start, creating the tree (ORB and classes), the first call.
 */
internal class StartupBench(private val options: BenchOptions, private val installation: Installation, private val report: Report) {
    private val javaCommand = Paths.get(System.getProperty("java.home"), "bin", "java").toString()

    suspend fun run() {
        report.section("start-up, whole processes (${options.startupRepetitions} runs each after ${options.processWarmups} warm-up; localisation system in a fixture JVM)")
        val missing = installation.cliMissing
        if (missing != null) {
            report.skipped("rtcoord", missing)
            return
        }
        FixtureProcess.start().use { fixtures ->
            commands(fixtures.address)
            script(fixtures.address)
            report.section("start-up breakdown: a probe on the CLI's class path, in a fresh JVM with the launcher's flags")
            breakdown(fixtures.address)
        }
    }

    private fun commands(address: String) {
        val launcher = installation.launcher.toString()
        val root = installation.root
        val jvm = TimedCommand("java -version (the JVM alone)", listOf(javaCommand) + JVM_FLAGS + "-version", root)
        val version = TimedCommand("rtcoord --version", listOf(launcher, "--version"), root)
        val commands = listOf(
            jvm,
            version,
            TimedCommand("rtcoord --help", listOf(launcher, "--help"), root),
            TimedCommand("rtcoord ls -l -R", listOf(launcher, "ls", "-l", "-R", "/$address/"), root),
        ) + listOfNotNull(installation.peer("rtls")?.let { TimedCommand("rtls -l -R", listOf(it.toString(), "-l", "-R", "/$address/"), root) })
        val times = commands.zip(timeInterleaved(commands, options.processWarmups, options.startupRepetitions))
        val bare = times.first().second
        for ((command, samples) in times) {
            val notes = when (command) {
                jvm -> "launcher's flags: ${JVM_FLAGS.joinToString(" ")}"
                else -> if (command.label.startsWith("rtcoord")) "%+.0f ms over the bare JVM".format((samples.median - bare.median) * 1000) else ""
            }
            report.row(command.label, samples, notes)
        }
        val ls = times.first { it.first.label == "rtcoord ls -l -R" }.second
        times.firstOrNull { it.first.label == "rtls -l -R" }?.let { (_, rtls) -> report.note("start-up: rtcoord ls -l -R is ${speedup(ls, rtls, "rtls")} on the 4-component localisation system") }
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
            val command = TimedCommand(
                RUN_CACHED, listOf(installation.launcher.toString(), "-n", address, "run", "--for", "1ms", script),
                installation.root, environment = mapOf("XDG_CACHE_HOME" to cache.toString()),
            )
            val first = command.run()
            report.value("rtcoord run, first time (compiles the script)", first.nanos / 1e9, "s", "into an empty cache")
            report.row(RUN_CACHED, timeInterleaved(listOf(command), options.processWarmups, options.startupRepetitions).single(), "coordinator started and stopped")
        } finally {
            cache.toFile().deleteRecursively()
        }
    }

    private fun breakdown(address: String) {
        val classPath = listOf(installation.cliJar!!, codeSource()).joinToString(java.io.File.pathSeparator)
        val command = listOf(javaCommand) + JVM_FLAGS + listOf("-cp", classPath, StartupProbe::class.java.name, address)
        val probes = List(options.processWarmups + options.startupRepetitions) {
            val launched = System.currentTimeMillis()
            val run = TimedCommand("startup probe", command, installation.root).run()
            val (entered, created, listed, classes) = run.output.single { it.startsWith("probe ") }.split(' ').drop(1).map { it.toLong() }
            listOf((entered - launched).toDouble(), created / 1e6, listed / 1e6, classes.toDouble())
        }.drop(options.processWarmups)
        report.row("JVM start to main", Samples(probes.map { it[0] }, "ms"), "process start, JVM init, loading the main class")
        report.row("RtcTree.create", Samples(probes.map { it[1] }, "ms"), "ORB init, loading core and JacORB classes")
        report.row("first call: list the name server", Samples(probes.map { it[2] }, "ms"), "connection, naming resolve and list")
        report.row("classes loaded by then", Samples(probes.map { it[3] }, "classes"))
    }

    /** Where this module's classes are: its jar or its classes directory. */
    private fun codeSource(): Path = Paths.get(StartupProbe::class.java.protectionDomain.codeSource.location.toURI())

    private companion object {
        const val RUN_CACHED = "rtcoord run --for 1ms, cached script"

        /** The flags `./rtcoord` starts its JVM with. */
        val JVM_FLAGS = listOf("-XX:TieredStopAtLevel=1", "-Xshare:auto")
    }
}
