package org.rtcoord

import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds

/**
 * How an [RtcTree] talks to the system.
 *
 * @property nameServers name servers added at creation: `host`, `host:port` or `corbaloc:` addresses.
 * @property callTimeout the deadline of every remote call unless the call gives its own.
 * @property concurrency how many remote calls discovery keeps in flight at once.
 * @property orb an ORB owned by the host application; the tree then neither configures nor destroys it.
 *   By default the tree creates and owns a JacORB ORB.
 * @property listenAddress the address the tree's own ORB listens on for callbacks (observers); by default
 *   loopback, never every interface.
 */
public class TreeConfig(
    public val nameServers: List<String> = emptyList(),
    public val callTimeout: Duration = 3.seconds,
    public val concurrency: Int = 32,
    public val orb: org.omg.CORBA.ORB? = null,
    public val listenAddress: String = "127.0.0.1",
) {
    init {
        require(callTimeout.isPositive()) { "callTimeout must be positive, was $callTimeout" }
        require(concurrency > 0) { "concurrency must be positive, was $concurrency" }
    }
}
