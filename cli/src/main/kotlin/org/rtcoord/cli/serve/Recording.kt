package org.rtcoord.cli.serve

import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import org.rtcoord.cli.json.OneLineJson

/**
 * A recorded run, as [LiveRecorder] writes it and `serve --replay` plays it: JSON lines, each a [RecordedUpdateJson]
 * whose data is an object, the first a `snapshot` and only the first.
 */
internal class Recording private constructor(private val updates: List<RecordedUpdateJson>) {
    /** The recording as one JSON array, which the page replays. */
    fun toJson(): String = OneLineJson.encodeToString(updates)

    /** How long the recorded run lasts: from its snapshot to its last line. */
    val length: Duration
        get() = (updates.last().at - updates.first().at).milliseconds

    /** The page's state at the start: the snapshot's data. */
    fun snapshot(): String = OneLineJson.encodeToString(updates.first().data)

    companion object {
        private val KINDS = setOf("snapshot", "network", "coordinator", "event")

        /** One line of a recording: [kind] and the page's [data], at [at] (epoch milliseconds). */
        fun line(kind: String, at: Long, data: JsonElement): String =
            OneLineJson.encodeToString(RecordedUpdateJson(kind, at, data))

        /** Reads [file]; a file that is not a recording fails with the line that says why. */
        fun read(file: Path): Recording {
            val lines =
                try {
                    Files.readAllLines(file)
                } catch (e: IOException) {
                    throw IllegalArgumentException("cannot read the recording $file: ${e.message ?: e}", e)
                }
            val updates =
                lines
                    .withIndex()
                    .filter { it.value.isNotBlank() }
                    .map { (index, line) ->
                        val update = decode(line)
                        require(update != null && update.kind in KINDS && update.data is JsonObject) {
                            "$file:${index + 1}: not a recording line (written by serve --record): ${line.take(60)}"
                        }
                        IndexedValue(index, update)
                    }
            require(updates.isNotEmpty()) { "$file is empty: a recording starts with a snapshot line" }
            updates.forEachIndexed { position, (index, update) ->
                require((position == 0) == (update.kind == "snapshot")) {
                    "$file:${index + 1}: " +
                        if (position == 0) "a recording starts with a snapshot line, not ${update.kind}"
                        else "a second snapshot line"
                }
            }
            return Recording(updates.map { it.value })
        }

        /** [line] decoded, or null when it is not a recording line's JSON. */
        private fun decode(line: String): RecordedUpdateJson? =
            try {
                OneLineJson.decodeFromString<RecordedUpdateJson>(line)
            } catch (e: SerializationException) {
                null
            }
    }
}
