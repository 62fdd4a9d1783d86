package org.rtcoord.cli

import java.io.File
import java.io.IOException
import java.lang.management.ManagementFactory
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes
import kotlinx.coroutines.runInterruptible

/**
 * Compiles a coordinator script in a JVM of its own, `rtcoord check SCRIPT`, which keeps what it compiles in the script
 * cache: the JVM that then runs the coordinator takes it from there and never loads the Kotlin compiler. A JVM keeps
 * the compiler's classes and heap for good once it has loaded them: `rtcoord run` of the localisation coordinator was
 * 268 MB resident for as long as it ran after compiling its script itself, against 81 MB when it started from the
 * cache. The launcher asks for it for `run` (`-Drtcoord.compile=apart`), as does a JVM without the compiler's jars
 * ([CompilerJars]), which that other JVM is given; in-process runs (tests, a host application) compile where they run.
 * A script with errors is not compiled again here to find them: the other JVM's are reported.
 */
internal object CompilerProcess {
    private const val PROPERTY = "rtcoord.compile"

    /** Whether scripts are compiled apart: the launcher says so. */
    val wanted: Boolean
        get() = System.getProperty(PROPERTY) == "apart"

    /**
     * Compiles [script] into the cache in another JVM, the same Java with this one's options and class path (and the
     * compiler's jars, when this one lacks them). Returns null when it compiled, else the problems to report: the
     * script's own (`file:line:col: message` lines, as `rtcoord check` prints them), or why that JVM could not compile
     * it (it could not start, or took longer than [timeout]).
     */
    suspend fun compile(script: Path, timeout: Duration = 5.minutes): List<String>? =
        // On the caller's thread, which has nothing else to do yet: kotlinx's IO threads, once started, stay for as
        // long as the coordinator runs (two of them in every `run` that had compiled its script).
        runInterruptible {
            val java = Path.of(System.getProperty("java.home"), "bin", "java").toString()
            val options = compilerOptions(ManagementFactory.getRuntimeMXBean().inputArguments)
            val classPath =
                listOf(System.getProperty("java.class.path"), if (CompilerJars.present) "" else CompilerJars.classPath)
                    .filter { it.isNotEmpty() }
                    .joinToString(File.pathSeparator)
            val command = listOf(java) + options + listOf("-cp", classPath, MAIN, "check", "$script")
            val errors = Files.createTempFile("rtcoord-compile", ".txt")
            try {
                val process =
                    try {
                        ProcessBuilder(command)
                            .redirectError(errors.toFile())
                            .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                            .start()
                    } catch (e: IOException) {
                        return@runInterruptible listOf("$script: the compiler's JVM could not start: ${e.message}")
                    }
                try {
                    if (!process.waitFor(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS)) {
                        process.destroyForcibly()
                        return@runInterruptible listOf("$script: not compiled within $timeout")
                    }
                } catch (e: InterruptedException) {
                    process.destroyForcibly()
                    throw e
                }
                if (process.exitValue() == 0) null
                else
                    Files.readAllLines(errors)
                        .filter { it.isNotBlank() }
                        .ifEmpty {
                            listOf("$script: the compiler's JVM exited with ${process.exitValue()}")
                        }
            } finally {
                Files.deleteIfExists(errors)
            }
        }

    /**
     * The compiler's JVM options, from this JVM's [options]: all but the launcher's class archive flags, which name
     * this JVM's archive or the list of classes it is made from, for the other to neither write nor map, and the
     * property that would make it compile apart in turn.
     */
    fun compilerOptions(options: List<String>): List<String> = options.filterNot {
        it.startsWith("-XX:ArchiveClassesAtExit") ||
            it.startsWith("-XX:DumpLoadedClassList") ||
            it.startsWith("-XX:SharedArchiveFile") ||
            it.startsWith("-D$PROPERTY=")
    }

    /** The class the launcher runs. */
    private const val MAIN = "org.rtcoord.cli.MainKt"
}
