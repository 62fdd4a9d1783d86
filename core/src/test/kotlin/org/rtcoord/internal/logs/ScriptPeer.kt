package org.rtcoord.internal.logs

import java.io.File
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.Paths
import java.util.concurrent.TimeUnit
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import org.junit.jupiter.api.Assertions.fail
import org.junit.jupiter.api.Assumptions.assumeTrue
import org.rtcoord.fixtures.Peers

/**
 * Runs a snippet in a peer's interpreter, [command] followed by its arguments, and returns what it printed (stdout and
 * stderr together); fails with that output unless it exits 0 within [timeout].
 */
internal fun runScript(
    command: List<String>,
    environment: Map<String, String> = emptyMap(),
    timeout: Duration = 60.seconds,
): String {
    val output = Files.createTempFile("forward-peer", ".log").toFile()
    try {
        val builder = ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output)
        builder.environment().putAll(environment)
        val process = builder.start()
        if (!process.waitFor(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS)) {
            process.destroyForcibly().waitFor()
            fail<Unit>("${command.first()} did not finish within $timeout:\n${output.readText()}")
        }
        val printed = output.readText()
        if (process.exitValue() != 0) fail<Unit>("${command.first()} exited ${process.exitValue()}:\n$printed")
        return printed
    } finally {
        output.delete()
    }
}

/**
 * Node.js and its fluent-logger, which `scripts/peers.sh` installs in the peers' `node` folder where npm is. Missing,
 * the calling test is skipped, saying why; in CI it fails when npm is there (peers.sh should have installed it).
 */
internal object NodeFluentLogger {
    const val VERSION = "3.4.1"

    /** The folder whose `node_modules` holds fluent-logger: NODE_PATH for `node`. */
    private val modules: Path = Peers.home.resolve("node").resolve("node_modules")

    /** `node`, with NODE_PATH, or the test skipped. */
    fun require(): Pair<String, Map<String, String>> {
        val node = onPath("node")
        val installed = Files.isRegularFile(modules.resolve("fluent-logger").resolve("package.json"))
        if (node == null || !installed) {
            val why =
                if (node == null) "node is not on the PATH: the tests on Node.js's fluent-logger need it"
                else "fluent-logger@$VERSION is not installed in $modules: run scripts/peers.sh (needs npm)"
            if (System.getenv("CI") != null && onPath("npm") != null) fail<Unit>(why) else assumeTrue(false, why)
        }
        return node.toString() to mapOf("NODE_PATH" to modules.toString())
    }

    private fun onPath(name: String): Path? =
        System.getenv("PATH")
            .orEmpty()
            .split(File.pathSeparator)
            .filter { it.isNotEmpty() }
            .map { Paths.get(it, name) }
            .firstOrNull { Files.isExecutable(it) }
}
