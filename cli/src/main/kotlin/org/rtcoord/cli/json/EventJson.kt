package org.rtcoord.cli.json

import java.time.Instant
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.KeepGeneratedSerializer
import kotlinx.serialization.Serializable
import org.rtcoord.RtcEvent
import org.rtcoord.RtcPath
import org.rtcoord.WatchMethodChanged

/**
 * An event as `watch --json` prints it (one a line) and the live view's timeline carries it: one flat object, when and
 * where first, then the [detail]'s fields and, for events about it, the [watch] method's. Also what `watch` finds
 * present when it starts (`Present`, `NameServerLost`, `ManagerDied`) and the data rates of `watch --data`
 * (`DataRate`).
 */
@OptIn(ExperimentalSerializationApi::class)
@KeepGeneratedSerializer
@Serializable(with = EventJson.Flat::class)
internal class EventJson(
    /** When the tree noticed it, ISO-8601 in UTC. */
    val time: String,
    /** The path of its source. */
    val path: String,
    /** What happened: the event type's name, `StateChanged` and so on. */
    val event: String,
    /** Its place among the tree's events; absent from what `watch` found present. */
    val sequence: Long? = null,
    /** The event's own fields. */
    @Spread val detail: EventDetail,
    /** How its component is watched, for `Present` and `WatchMethodChanged`. */
    @Spread val watch: WatchMethodJson? = null,
) {
    /** Writes [EventJson] as one flat object. */
    object Flat : SpreadingSerializer<EventJson>(generatedSerializer())

    companion object {
        /** [millis] since the epoch as events' `time`. */
        private fun time(millis: Long): String = Instant.ofEpochMilli(millis).toString()

        /** Something that is so when `watch` starts, or a rate it measured: no sequence. */
        fun found(millis: Long, path: RtcPath, detail: EventDetail, watch: WatchMethodJson? = null): EventJson =
            EventJson(time(millis), path.toString(), detail.javaClass.simpleName, detail = detail, watch = watch)

        /** [event] as the JSON gives it, with how its component is watched now when that is what changed. */
        fun of(event: RtcEvent): EventJson =
            EventJson(
                time(event.noticedAt),
                event.path.toString(),
                event.javaClass.simpleName,
                event.sequence,
                eventDetail(event),
                (event as? WatchMethodChanged)?.let { WatchMethodJson.of(it.new) },
            )
    }
}
