package org.rtcoord.cli

import java.net.InetSocketAddress
import java.net.ServerSocket
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.FluentLogSender

/**
 * `logs` and `watch --logs`: the records the fixtures' components send over the forward protocol, printed as they come,
 * from the component that sent them, filtered by level and text.
 */
class LogsCommandTest {
    private val localisation = Localisation()
    private val port = ServerSocket(0).use { it.localPort }
    private val address = "127.0.0.1:$port"
    private val sender = FluentLogSender(InetSocketAddress("127.0.0.1", port), "manager_slave")

    @AfterEach
    fun stop() {
        sender.close()
        localisation.close()
    }

    /** Sends [message] as [name]'s once the command listens: until then, the sender finds nobody. */
    private fun logs(name: String, level: String, message: String) =
        await("the command to listen on $address") { sender.send(name, level, message) }

    @Test
    fun `logs prints each record at or above the level that matches, from its component`() {
        val printed =
            RunningCommand(
                    "-n",
                    localisation.naming.address,
                    "logs",
                    "--logs-listen",
                    address,
                    "--level",
                    "warn",
                    "--grep",
                    "time",
                )
                .use { logging ->
                    logs("laser0", "INFO", "scan timeout")
                    logs("laser0", "WARN", "intensity low")
                    logs("laser0", "WARNING", "scan timeout")
                    logs("gyro0", "ERROR", "drift timed out")
                    logging.awaitLines("the two records that pass", 2) { it.isNotEmpty() }
                    logging.stop()
                }
        assertEquals(0, printed.statusCode, printed.stderr)
        val lines = printed.stdout.lines().filter { it.isNotEmpty() }
        assertEquals(
            listOf(
                "${localisation.path("laser0.rtc")} logged WARN laser0: scan timeout",
                "${localisation.path("gyro0.rtc")} logged ERROR gyro0: drift timed out",
            ),
            lines.map { it.substringAfter(' ').substringAfter(' ') },
            lines.joinToString("\n"),
        )
        assertTrue(printed.stderr.startsWith("rtcoord: receiving log records on $address"), printed.stderr)
    }

    @Test
    fun `watch --logs prints records among the events, as JSON too`() {
        val printed =
            RunningCommand("--json", "watch", "--logs", "--logs-listen", address, localisation.path("laser0.rtc"))
                .use { watching ->
                    watching.awaitLine("the laser's present line") { "\"Present\"" in it }
                    logs("laser0", "WARN", "scan timeout")
                    logs("gyro0", "WARN", "not the laser's")
                    logs("laser0", "ERROR", "scan failed")
                    watching.awaitLine("the laser's error") { "scan failed" in it }
                    watching.stop()
                }
        val records = printed.ok().lines().filter { "\"LogRecord\"" in it }
        assertEquals(2, records.size, records.joinToString("\n"))
        assertTrue(
            Regex(
                    """\{"time":"[^"]+","path":"${Regex.escape(localisation.path("laser0.rtc"))}","event":"LogRecord","sequence":\d+,"loggedAt":"[^"]+","level":"WARN","logger":"laser0","message":"scan timeout","pid":\d+,"host":"[^"]+","manager":"manager_slave","tag":"rtclog"\}"""
                )
                .matches(records.first()),
            records.first(),
        )
    }
}
