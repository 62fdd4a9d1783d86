package org.rtcoord.cli.serve

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.cli.Localisation
import org.rtcoord.cli.failure
import org.rtcoord.cli.ok
import org.rtcoord.cli.runRtcoord
import org.rtcoord.cli.usageError
import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration.Companion.milliseconds

/** `rtcoord record`, and reading a recording: what serve --replay accepts, and the one line that says why it refuses the rest. */
class RecordingTest {
    @TempDir
    lateinit var directory: Path

    private fun refusal(vararg lines: String): String {
        val file = directory.resolve("run.jsonl")
        Files.write(file, lines.toList())
        return assertThrows<IllegalArgumentException> { Recording.read(file) }.message!!.replace(file.toString(), "FILE")
    }

    @Test
    fun `a recording is its lines as one array, the snapshot's data first`() {
        val file = directory.resolve("run.jsonl")
        Files.write(file, listOf(Recording.line("snapshot", 1, "{\"network\":{}}"), Recording.line("event", 2, "{\"seq\":1}")))
        val recording = Recording.read(file)
        assertEquals("""[{"kind":"snapshot","at":1,"data":{"network":{}}},{"kind":"event","at":2,"data":{"seq":1}}]""", recording.toJson())
        assertEquals("""{"network":{}}""", recording.snapshot())
        assertEquals(1.milliseconds, recording.length)
    }

    @Test
    fun `serve --at picks a moment of a replayed recording, one within it`() {
        val file = directory.resolve("short.jsonl")
        Files.write(file, listOf(Recording.line("snapshot", 1_000, "{\"network\":{}}"), Recording.line("event", 3_500, "{\"seq\":1}")))
        assertEquals("rtcoord: $file lasts 2.5s: it has no moment 12.5s after its start", runRtcoord("serve", "--replay", file.toString(), "--at", "12.5s").failure())
        assertTrue("--at is a moment of a recording" in runRtcoord("serve", "--at", "1s").usageError())
    }

    @Test
    fun `rtcoord record writes a recording that serve --replay reads`() {
        Localisation().use { localisation ->
            val file = directory.resolve("recorded.jsonl")
            assertEquals("recording ${localisation.host} to $file\n", runRtcoord("record", file.toString(), localisation.host, "--for", "1s").ok())
            val snapshot = Recording.read(file).snapshot()
            assertTrue(localisation.path("laser0.rtc") in snapshot, snapshot.take(200))
        }
    }

    @Test
    fun `what is not a recording is refused with the line that says why`() {
        assertEquals("FILE is empty: a recording starts with a snapshot line", refusal())
        assertEquals("FILE:1: a recording starts with a snapshot line, not event", refusal(Recording.line("event", 1, "{}")))
        assertEquals("FILE:2: not a recording line (written by serve --record): hello", refusal(Recording.line("snapshot", 1, "{}"), "hello"))
        assertEquals("FILE:2: a second snapshot line", refusal(Recording.line("snapshot", 1, "{}"), Recording.line("snapshot", 2, "{}")))
    }
}
