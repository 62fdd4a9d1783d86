package org.rtcoord.cli.serve

import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.encodeToJsonElement
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.cli.Localisation
import org.rtcoord.cli.failure
import org.rtcoord.cli.json.EventDetail
import org.rtcoord.cli.json.EventJson
import org.rtcoord.cli.json.OneLineJson
import org.rtcoord.cli.ok
import org.rtcoord.cli.runRtcoord
import org.rtcoord.cli.usageError

/**
 * `rtcoord record`, and reading a recording: what serve --replay accepts, and the one line that says why it refuses the
 * rest.
 */
class RecordingTest {
    @TempDir lateinit var directory: Path

    private fun line(kind: String, at: Long, json: String): String =
        Recording.line(kind, at, Json.parseToJsonElement(json))

    private fun refusal(vararg lines: String): String {
        val file = directory.resolve("run.jsonl")
        Files.write(file, lines.toList())
        return assertThrows<IllegalArgumentException> { Recording.read(file) }
            .message!!
            .replace(file.toString(), "FILE")
    }

    @Test
    fun `a recording is its lines as one array, the snapshot's data first`() {
        val file = directory.resolve("run.jsonl")
        Files.write(file, listOf(line("snapshot", 1, "{\"network\":{}}"), line("event", 2, "{\"seq\":1}")))
        val recording = Recording.read(file)
        assertEquals(
            """[{"kind":"snapshot","at":1,"data":{"network":{}}},{"kind":"event","at":2,"data":{"seq":1}}]""",
            recording.toJson(),
        )
        assertEquals("""{"network":{}}""", recording.snapshot())
        assertEquals(1.milliseconds, recording.length)
    }

    @Test
    fun `serve --at picks a moment of a replayed recording, one within it`() {
        val file = directory.resolve("short.jsonl")
        Files.write(file, listOf(line("snapshot", 1_000, "{\"network\":{}}"), line("event", 3_500, "{\"seq\":1}")))
        assertEquals(
            "rtcoord: $file lasts 2.5s: it has no moment 12.5s after its start",
            runRtcoord("serve", "--replay", file.toString(), "--at", "12.5s").failure(),
        )
        assertTrue("--at is a moment of a recording" in runRtcoord("serve", "--at", "1s").usageError())
    }

    @Test
    fun `rtcoord record writes a recording that serve --replay reads`() {
        Localisation().use { localisation ->
            val file = directory.resolve("recorded.jsonl")
            assertEquals(
                "recording ${localisation.host} to $file\n",
                runRtcoord("record", file.toString(), localisation.host, "--for", "1s").ok(),
            )
            val snapshot = Recording.read(file).snapshot()
            assertTrue(localisation.path("laser0.rtc") in snapshot, snapshot.take(200))
        }
    }

    @Test
    fun `what is not a recording is refused with the line that says why`() {
        assertEquals("FILE is empty: a recording starts with a snapshot line", refusal())
        assertEquals("FILE:1: a recording starts with a snapshot line, not event", refusal(line("event", 1, "{}")))
        assertEquals(
            "FILE:2: not a recording line (written by serve --record): hello",
            refusal(line("snapshot", 1, "{}"), "hello"),
        )
        assertEquals("FILE:2: a second snapshot line", refusal(line("snapshot", 1, "{}"), line("snapshot", 2, "{}")))
    }

    @Test
    fun `a line that does not decode is refused by its number in the file, blank lines counted`() {
        val snapshot = line("snapshot", 1, "{}")
        // A run killed while it wrote its last line.
        val cut = line("event", 2, "{\"seq\":1}").dropLast(4)
        assertEquals("FILE:3: not a recording line (written by serve --record): $cut", refusal(snapshot, "", cut))
        val unknown = """{"kind":"sound","at":2,"data":{}}"""
        assertEquals("FILE:2: not a recording line (written by serve --record): $unknown", refusal(snapshot, unknown))
        val notAnObject = """{"kind":"event","at":2,"data":[1]}"""
        assertEquals(
            "FILE:2: not a recording line (written by serve --record): $notAnObject",
            refusal(snapshot, notAnObject),
        )
        val noTime = """{"kind":"event","data":{}}"""
        assertEquals("FILE:2: not a recording line (written by serve --record): $noTime", refusal(snapshot, noTime))
    }

    @Test
    fun `what the view sends is replayed as it was sent`() {
        val event =
            EventJson(
                "2026-11-29T00:00:00.999Z",
                "/localhost/laser0.rtc",
                "StateChanged",
                5,
                EventDetail.StateChanged(0, "INACTIVE", "ACTIVE"),
            )
        val entry =
            OneLineJson.encodeToJsonElement(
                TimelineEntryJson(7, 1_000, event, "state", event.path, "state in context 0: INACTIVE -> ACTIVE", 999)
            )
        val snapshot =
            OneLineJson.encodeToJsonElement(
                LiveSnapshotJson(null, null, listOf(), operable = false, serverTime = "2026-11-29T00:00:00Z")
            )
        val file = directory.resolve("typed.jsonl")
        Files.write(file, listOf(Recording.line("snapshot", 1_000, snapshot), Recording.line("event", 1_250, entry)))
        val recording = Recording.read(file)
        assertEquals(
            JsonArray(listOf(recorded("snapshot", 1_000, snapshot), recorded("event", 1_250, entry))),
            Json.parseToJsonElement(recording.toJson()),
        )
        assertEquals(snapshot, Json.parseToJsonElement(recording.snapshot()))
        assertEquals(250.milliseconds, recording.length)
        assertEquals("StateChanged", entry.jsonObject.getValue("event").jsonPrimitive.content)
    }

    private fun recorded(kind: String, at: Long, data: JsonElement): JsonElement =
        JsonObject(mapOf("kind" to JsonPrimitive(kind), "at" to JsonPrimitive(at), "data" to data))
}
