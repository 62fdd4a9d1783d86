package org.rtcoord.cli

import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import org.junit.jupiter.api.Assertions.assertTrue

/** What a process printed and how it ended: an expected run is written as `ProcessRun(0, "out\n", "")`. */
data class ProcessRun(val status: Int, val stdout: String, val stderr: String) {
    /** How long it ran, in milliseconds; left out of equality, so an expected run need not guess it. */
    var millis: Long = 0
}

/**
 * Runs [command] to its end (a minute at most), with [path] as its PATH if given and [environment] added; the name
 * servers of the environment rtcoord would read are removed, so only the command line names them.
 */
fun runProcess(
    command: List<String>,
    path: String? = null,
    environment: Map<String, String> = emptyMap(),
): ProcessRun {
    val builder = ProcessBuilder(command)
    path?.let { builder.environment()["PATH"] = it }
    builder.environment().putAll(environment)
    builder.environment().remove("RTCTREE_NAMESERVERS")
    builder.environment().remove("RTCOORD_NAMESERVERS")
    val started = System.nanoTime()
    val process = builder.start()
    // Both streams at once: a process that fills the one not being read would never end.
    val stderr = CompletableFuture.supplyAsync { process.errorStream.bufferedReader().readText() }
    val stdout = process.inputStream.bufferedReader().readText()
    assertTrue(process.waitFor(60, TimeUnit.SECONDS), "${command.joinToString(" ")} did not end")
    return ProcessRun(process.exitValue(), stdout, stderr.get()).also {
        it.millis = (System.nanoTime() - started) / 1_000_000
    }
}
