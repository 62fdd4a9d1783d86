package org.rtcoord.cli

import com.github.ajalt.clikt.testing.CliktCommandTestResult
import com.github.ajalt.clikt.testing.test
import java.net.ServerSocket
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.rtcoord.runtime.RtSystem
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/** The paper's localisation system on an in-process naming service, for `rtcoord` to look at. */
class Localisation : AutoCloseable {
    val naming: NamingService = NamingService.start()
    val system: RtSystem = Scenarios.localisation(naming.corbaloc)

    /** `/127.0.0.1:PORT/<host>.host_cxt` */
    val host: String = "/${naming.address}/${RuntimeProcess.hostContext}"

    /** [name] in the host context. */
    fun path(name: String): String = "$host/$name"

    override fun close() {
        system.close()
        naming.close()
    }
}

/**
 * Runs `rtcoord ARGUMENTS` in this JVM through Clikt's test harness, which captures what the command echoes and its
 * exit status. The environment holds only [environment].
 */
fun runRtcoord(vararg arguments: String, environment: Map<String, String> = emptyMap()): CliktCommandTestResult {
    val command = rtcoord()
    return command.test(arguments.toList(), envvars = environment) { command.execute(it) }
}

/** Asserts a successful run that printed nothing on stderr, and returns its stdout. */
fun CliktCommandTestResult.ok(): String {
    assertEquals(0, statusCode, "exit status; stderr: $stderr")
    assertEquals("", stderr, "stderr")
    return stdout
}

/** Asserts a failed run: status 1, nothing on stdout, a single `rtcoord: ...` line on stderr; returns that line. */
fun CliktCommandTestResult.failure(): String {
    assertEquals(1, statusCode, "exit status; stdout: $stdout; stderr: $stderr")
    assertEquals("", stdout, "stdout")
    val lines = stderr.lines().filter { it.isNotEmpty() }
    assertEquals(1, lines.size, "one line on stderr: $stderr")
    assertTrue(lines.single().startsWith("rtcoord: "), lines.single())
    return lines.single()
}

/** Asserts a usage error: status 2, Clikt's usage message on stderr; returns stderr. */
fun CliktCommandTestResult.usageError(): String {
    assertEquals(2, statusCode, "exit status; stdout: $stdout; stderr: $stderr")
    assertEquals("", stdout, "stdout")
    assertTrue(stderr.startsWith("Usage: rtcoord"), stderr)
    return stderr
}

/** A loopback address where nothing listens: a port the system just handed out and took back. */
fun deadNameServer(): String = "127.0.0.1:${ServerSocket(0).use { it.localPort }}"
