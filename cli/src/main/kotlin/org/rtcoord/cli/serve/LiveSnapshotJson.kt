package org.rtcoord.cli.serve

import kotlinx.serialization.Serializable

/**
 * Everything a page starts from (`GET /api/snapshot`, the `snapshot` event, a recording's first line): the network with
 * its states, the coordinator's state (null without one), the recent timeline, whether the page may operate components,
 * and the server's clock.
 */
@Serializable
internal class LiveSnapshotJson(
    /** Null until the view has read the system. */
    val network: NetworkJson?,
    val coordinator: CoordinatorJson?,
    val events: List<TimelineEntryJson>,
    val operable: Boolean,
    /** ISO-8601 in UTC. */
    val serverTime: String,
)
