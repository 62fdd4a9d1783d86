package org.rtcoord.cli

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig

/** `print`: rtprint, working, against the fixtures' real corba_cdr data; `watch --data`: port rates. */
class PrintCommandTest {
    private val localisation = Localisation()

    @AfterEach fun stop() = localisation.close()

    /** The tap connectors on [port], read by a tree of the test's own. */
    private fun taps(port: String): List<String> =
        RtcTree(TreeConfig(listOf(localisation.naming.address))).use { tree ->
            runBlocking { tree.port(localisation.path(port)).connections() }
                .map { it.id }
                .filter { it.startsWith("rtcoord-tap-") }
        }

    @Test
    fun `prints --count samples, one line each with time stamp, type and value, and leaves no tap behind`() {
        val lines =
            runRtcoord("print", localisation.path("laser0.rtc:laser"), "--count", "3").ok().lines().filter {
                it.isNotEmpty()
            }
        assertEquals(3, lines.size, lines.joinToString("\n"))
        val line = Regex("""\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d(\.\d+)?Z  TimedDoubleSeq  \[([4-6]\.0 ){7}[4-6]\.0]""")
        assertTrue(lines.all { line.matches(it) }, lines.joinToString("\n"))
        assertEquals(emptyList<String>(), taps("laser0.rtc:laser"))
    }

    @Test
    fun `--json prints one object per sample, and --for stops it`() {
        val started = System.nanoTime()
        val lines =
            runRtcoord("print", localisation.path("gyro0.rtc:gyro"), "--json", "--for", "1s").ok().lines().filter {
                it.isNotEmpty()
            }
        assertTrue((System.nanoTime() - started) / 1_000_000 in 1_000..6_000)
        assertTrue(lines.size >= 5, "the gyro writes at 100 Hz: ${lines.size} lines")
        val json = Regex("""\{"time":"[^"]+","type":"TimedDouble","value":"-?\d+\.\d+(E-?\d+)?"}""")
        assertTrue(lines.all { json.matches(it) }, lines.take(3).joinToString("\n"))
        assertEquals(emptyList<String>(), taps("gyro0.rtc:gyro"))
    }

    @Test
    fun `refuses an in-port in one line`() {
        val message = runRtcoord("print", localisation.path("laser_localise0.rtc:laser"), "--count", "1").failure()
        assertTrue(message.contains("only an out-port's data can be tapped"), message)
    }

    @Test
    fun `watch --data prints each out-port's rate every second`() {
        val rate = Regex("""\S+ \S+ /\S+/laser0\.rtc:laser data (\d+\.\d) Hz""")
        val lines =
            RunningCommand("watch", "--data", localisation.path("laser0.rtc")).use { watching ->
                watching.awaitLines("two rates of the laser's port", 2) { rate.matches(it) }
                watching.awaitLine("the port's traffic") { it.endsWith("port laser sent data") }
                watching.stop().ok().lines()
            }
        val rates = lines.mapNotNull { rate.matchEntire(it)?.groupValues?.get(1)?.toDouble() }
        assertTrue(rates.size >= 2, lines.joinToString("\n"))
        assertTrue(rates.all { it in 20.0..140.0 }, "the laser runs at 100 Hz: $rates")
        assertTrue(
            lines.any { Regex("""\S+ \S+ /\S+/laser0\.rtc port laser sent data""").matches(it) },
            lines.joinToString("\n"),
        )
        assertEquals(emptyList<String>(), taps("laser0.rtc:laser"))
    }
}
