package org.rtcoord.bench

import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.TimeUnit
import kotlin.time.Duration
import kotlin.time.Duration.Companion.minutes

/**
 * A command run as a whole process, as a user runs it from a shell, timed from just before it is started to its exit.
 * Output goes to files, so reading it costs the command nothing; name server variables are removed from its environment
 * so only its arguments say what it talks to.
 */
internal class TimedCommand(
    val label: String,
    private val command: List<String>,
    private val directory: Path,
    private val environment: Map<String, String> = emptyMap(),
    private val timeout: Duration = 10.minutes,
) {
    /** One run: its wall time, and what it printed. */
    class Run(val nanos: Long, val output: List<String>, val errors: String)

    /** Runs the command once; fails naming it when it does not exit 0 within the timeout. */
    fun run(): Run {
        val output = Files.createTempFile("bench-out", ".txt")
        val errors = Files.createTempFile("bench-err", ".txt")
        try {
            val builder =
                ProcessBuilder(command)
                    .directory(directory.toFile())
                    .redirectOutput(output.toFile())
                    .redirectError(errors.toFile())
                    .redirectInput(ProcessBuilder.Redirect.from(java.io.File("/dev/null")))
            IGNORED_VARIABLES.forEach { builder.environment().remove(it) }
            builder.environment().putAll(environment)
            val start = System.nanoTime()
            val process = builder.start()
            if (!process.waitFor(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS)) {
                process.destroyForcibly().waitFor()
                error("$label did not finish within $timeout")
            }
            val nanos = System.nanoTime() - start
            val run = Run(nanos, Files.readAllLines(output), Files.readString(errors))
            check(process.exitValue() == 0) {
                "$label exited ${process.exitValue()}: ${run.errors.lineSequence().firstOrNull { it.isNotBlank() } ?: "(no message)"}"
            }
            return run
        } finally {
            Files.deleteIfExists(output)
            Files.deleteIfExists(errors)
        }
    }

    companion object {
        /** Name server variables, removed from a command's environment: only its arguments say what it talks to. */
        val IGNORED_VARIABLES = listOf("RTCOORD_NAMESERVERS", "RTCTREE_NAMESERVERS", "RTCOORD_CWD", "RTCSH_CWD")
    }
}

/**
 * Runs each of [commands] [warmups] times untimed, then [repetitions] times interleaved, so load that comes and goes
 * weighs on all of them alike; [inspect] sees each timed run. Returns each command's wall times in seconds.
 */
internal fun timeInterleaved(
    commands: List<TimedCommand>,
    warmups: Int,
    repetitions: Int,
    inspect: (TimedCommand, TimedCommand.Run) -> Unit = { _, _ -> },
): List<Samples> {
    repeat(warmups) { commands.forEach { it.run() } }
    val times = commands.map { mutableListOf<Long>() }
    repeat(repetitions) {
        commands.forEachIndexed { index, command ->
            val run = command.run()
            inspect(command, run)
            times[index] += run.nanos
        }
    }
    return times.map { Samples.seconds(it) }
}
