package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
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
 * `rtcoord run` from the built jar, stopped as a service manager stops it. A class apart from [CliJarIT], so that the
 * build's test JVMs run its rounds beside the jar's other tests.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class SigtermIT {
    private val localisation = Localisation()
    private val jar: Path = Paths.get(System.getProperty("rtcoord.cli.jar"))

    @AfterAll fun stop() = localisation.close()

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
                ProcessRun(process.exitValue(), printed.joinToString("\n"), stderr.get())
            }
        val unclean = outcomes.filter {
            it.status != 0 ||
                it.stderr.isNotEmpty() ||
                it.stdout.lines().none { line ->
                    line.endsWith("stopped by SIGTERM; 0 handler failures; 0 failed actions")
                }
        }
        assertEquals(emptyList<ProcessRun>(), unclean, "of $SIGTERM_ROUNDS runs stopped by SIGTERM")
        assertEquals(emptySet<String>(), localisation.system.component("gyro0").observerIds)
    }
}

/** How many times the SIGTERM test stops `run`: the failure it guards against came in about one stop of three. */
private const val SIGTERM_ROUNDS = 6
