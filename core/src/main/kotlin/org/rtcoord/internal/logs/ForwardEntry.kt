package org.rtcoord.internal.logs

import java.net.InetSocketAddress
import java.time.Instant

/**
 * One event as the Fluentd forward protocol carried it: its [tag], its [time] (to the nanosecond when the sender gave
 * an EventTime), its [record] and the [sender] whose connection brought it.
 *
 * The record's values are what MessagePack held: String, Long, Double, Boolean, ByteArray, List, Map (with String keys)
 * or null; an unsigned integer above Long's range comes as a Double, an extension value as its data's bytes.
 */
internal class ForwardEntry(
    val tag: String,
    val time: Instant,
    val record: Map<String, Any?>,
    val sender: InetSocketAddress,
) {
    override fun toString(): String = "ForwardEntry($tag, $time, $record, from $sender)"
}
