package org.rtcoord.cli.serve

import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds

/**
 * A recorded run, as [LiveRecorder] writes it and `serve --replay` plays it: JSON lines
 * `{"kind":K,"at":EPOCH_MILLIS,"data":…}`, K one of the page's update kinds, the first a `snapshot`.
 */
internal class Recording private constructor(private val lines: List<String>) {
    /** The recording as one JSON array, which the page replays. */
    fun toJson(): String = lines.joinToString(",", "[", "]")

    /** How long the recorded run lasts: from its snapshot to its last line. */
    val length: Duration get() = (at(lines.last()) - at(lines.first())).milliseconds

    /** The page's state at the start: the snapshot's data. */
    fun snapshot(): String = lines.first().substringAfter(DATA).removeSuffix("}")

    companion object {
        private val KINDS = setOf("snapshot", "network", "coordinator", "event")
        private val LINE = Regex("""^\{"kind":"([a-z]+)","at":(\d+),"data":[\[{].*}$""")
        private const val DATA = "\"data\":"

        private fun at(line: String): Long = LINE.find(line)?.groupValues?.get(2)?.toLong() ?: 0

        /** One line of a recording: [kind] and the page's [json] data, at [at] (epoch milliseconds). */
        fun line(kind: String, at: Long, json: String): String = "{\"kind\":\"$kind\",\"at\":$at,$DATA$json}"

        /** Reads [file]; a file that is not a recording fails with the line that says why. */
        fun read(file: Path): Recording {
            val lines = try {
                Files.readAllLines(file).filter { it.isNotBlank() }
            } catch (e: IOException) {
                throw IllegalArgumentException("cannot read the recording $file: ${e.message ?: e}", e)
            }
            require(lines.isNotEmpty()) { "$file is empty: a recording starts with a snapshot line" }
            lines.forEachIndexed { index, line ->
                val kind = LINE.find(line)?.groupValues?.get(1)
                require(kind != null && kind in KINDS) { "$file:${index + 1}: not a recording line (written by serve --record): ${line.take(60)}" }
                require((index == 0) == (kind == "snapshot")) {
                    "$file:${index + 1}: " + if (index == 0) "a recording starts with a snapshot line, not $kind" else "a second snapshot line"
                }
            }
            return Recording(lines)
        }
    }
}
