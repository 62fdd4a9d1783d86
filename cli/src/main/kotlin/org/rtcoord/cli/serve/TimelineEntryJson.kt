package org.rtcoord.cli.serve

import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.KeepGeneratedSerializer
import kotlinx.serialization.Serializable
import org.rtcoord.cli.json.EventJson
import org.rtcoord.cli.json.Spread
import org.rtcoord.cli.json.SpreadingSerializer

/**
 * A line of the page's timeline, numbered [seq] in the order the server sent them: an event (its fields spread in, as
 * `watch --json` gives them) or a log line from the coordinator or the server.
 */
@OptIn(ExperimentalSerializationApi::class)
@KeepGeneratedSerializer
@Serializable(with = TimelineEntryJson.Flat::class)
internal class TimelineEntryJson(
    val seq: Long,
    /** When the server sent it, in milliseconds since the epoch. */
    val sentAt: Long,
    /** The event, for an event's line. */
    @Spread val event: EventJson? = null,
    /** The timeline's filter group: `state`, `port`, `configuration`, `liveness`, `manager`, `structure`, or `log`. */
    val kind: String,
    /** An event's source path, or who logged the line (`coordinator`, `page`...). */
    val source: String,
    /** What happened, in words. */
    val text: String,
    /** When the tree noticed the event, in milliseconds since the epoch. */
    val noticedAt: Long? = null,
    /** When a log line was written, ISO-8601 in UTC (an event has its own `time`). */
    val time: String? = null,
) {
    /** Writes [TimelineEntryJson] as one flat object. */
    object Flat : SpreadingSerializer<TimelineEntryJson>(generatedSerializer())
}
