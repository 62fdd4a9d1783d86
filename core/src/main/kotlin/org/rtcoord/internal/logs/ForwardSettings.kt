package org.rtcoord.internal.logs

import java.net.InetSocketAddress
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * How a [ForwardInput] listens and what it accepts.
 *
 * @property address where it listens, on TCP and on UDP (the heartbeat); port 0 takes any free port.
 * @property sharedKey the key of Fluentd's shared-key handshake; null: no handshake, anyone may send.
 * @property selfHostname the name the handshake's PONG gives for this end.
 * @property maxRecordBytes the most one frame, or one entry of a packed frame once uncompressed, may take: the bound of
 *   what a connection buffers.
 * @property maxEntriesPerSecond the most entries one connection may send in a second; above it the connection is
 *   refused as a flood and closed.
 * @property frameTimeout how long a frame begun may take to arrive whole before its connection is closed.
 */
internal class ForwardSettings(
    val address: InetSocketAddress,
    val sharedKey: String? = null,
    val selfHostname: String = "rtcoord",
    val maxRecordBytes: Int = 1 shl 20,
    val maxEntriesPerSecond: Int = 50_000,
    val frameTimeout: Duration = 10.seconds,
) {
    init {
        require(maxRecordBytes > 0) { "maxRecordBytes must be positive, not $maxRecordBytes" }
        require(maxEntriesPerSecond > 0) { "maxEntriesPerSecond must be positive, not $maxEntriesPerSecond" }
        require(frameTimeout.isPositive()) { "frameTimeout must be positive, not $frameTimeout" }
    }
}
