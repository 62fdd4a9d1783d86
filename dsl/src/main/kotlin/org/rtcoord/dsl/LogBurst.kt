package org.rtcoord.dsl

import kotlin.time.Duration
import org.rtcoord.LogRecord
import org.rtcoord.Node
import org.rtcoord.RtcEvent

/**
 * Counts the records a rule on log records matches, for `logged(..., atLeast = 3, within = 10.seconds)`: the record
 * that makes [atLeast] matching ones from one sender within [within] (by when the tree received them) fires the rule,
 * and the count starts again from nothing, so a steady stream fires once for every [atLeast] records, not for each.
 */
internal class LogBurst(
    private val atLeast: Int,
    private val within: Duration,
    private val matches: (LogRecord) -> Boolean,
) : EventReading<LogRecord> {
    /** When each sender's matching records came, oldest first, by the sender's path. */
    private val times = HashMap<String, ArrayDeque<Long>>()

    override suspend fun prepare(node: Node): LogRecord? = null

    override fun translate(event: RtcEvent): LogRecord? {
        if (event !is LogRecord || !matches(event)) return null
        synchronized(times) {
            val seen = times.getOrPut(event.source.path.toString(), ::ArrayDeque)
            seen.addLast(event.noticedAt)
            while (seen.first() < event.noticedAt - within.inWholeMilliseconds) seen.removeFirst()
            if (seen.size < atLeast) return null
            seen.clear()
        }
        return event
    }
}
