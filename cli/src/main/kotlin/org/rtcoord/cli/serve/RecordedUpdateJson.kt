package org.rtcoord.cli.serve

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement

/**
 * One line of a recording ([Recording]): an update the page received, of [kind] (`snapshot`, `network`, `coordinator`
 * or `event`, the SSE event names), [at] a time in milliseconds since the epoch, with its [data] as the page received
 * it. A replay sends them all, as one array.
 */
@Serializable internal class RecordedUpdateJson(val kind: String, val at: Long, val data: JsonElement)
