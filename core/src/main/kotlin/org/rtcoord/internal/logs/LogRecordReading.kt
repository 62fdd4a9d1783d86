package org.rtcoord.internal.logs

import org.rtcoord.LogLevel
import org.rtcoord.LogRecord
import org.rtcoord.Node

/**
 * [entry] as a [LogRecord] from [source]: the fields OpenRTM-aist sends (`name`, `level`, `pid`, `host`, `manager`,
 * `message`; FluentLogger.py and C++'s `FluentBit.cpp` send the same keys, every value a string), read leniently, so
 * that a record from another Fluentd sender is still shown: its text from `message`, else `log` (Fluent Bit's inputs),
 * else the whole record; a level it does not name is [LogLevel.INFO].
 */
internal fun logRecordOf(entry: ForwardEntry, source: Node): LogRecord {
    val record = entry.record
    return LogRecord(
        source = source,
        loggedAt = entry.time.toEpochMilli(),
        level = record.text("level")?.let(LogLevel::named) ?: LogLevel.INFO,
        logger = record.text("name") ?: "",
        message = record.text("message") ?: record.text("log") ?: record.toString(),
        pid = record.text("pid")?.let { it.toLongOrNull() ?: it.trim().toLongOrNull() },
        host = record.text("host"),
        manager = record.text("manager"),
        tag = entry.tag,
    )
}

/** The logger's and the manager's names of [entry], which say whom it is from (see [LogSenders]). */
internal fun senderNamesOf(entry: ForwardEntry): Pair<String, String?> =
    (entry.record.text("name") ?: "") to entry.record.text("manager")

/** A value as text: senders send strings as MessagePack str or bin. */
private fun Map<String, Any?>.text(key: String): String? =
    when (val value = get(key)) {
        null -> null
        is ByteArray -> String(value, Charsets.UTF_8)
        else -> value.toString()
    }
