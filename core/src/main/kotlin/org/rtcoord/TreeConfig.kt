package org.rtcoord

import org.rtcoord.internal.ListenAddress
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
 * @property listenAddress the one address the tree's own ORB listens on for callbacks (observers), and the
 *   only one its object references carry. By default (null) the address this host uses to reach the first
 *   name server the tree has when it makes its first remote call: loopback for a name server on this
 *   host or when there is none. Name servers added later must be able to reach that address (their
 *   components call observers back there); give an address explicitly when they cannot. `0.0.0.0`
 *   listens on every interface, and only when given.
 */
public class TreeConfig(
    public val nameServers: List<String> = emptyList(),
    public val callTimeout: Duration = 3.seconds,
    public val concurrency: Int = 32,
    public val orb: org.omg.CORBA.ORB? = null,
    public val listenAddress: String? = null,
) {
    init {
        require(callTimeout.isPositive()) { "callTimeout must be positive, was $callTimeout" }
        require(concurrency > 0) { "concurrency must be positive, was $concurrency" }
        val problem = listenAddress?.let(::listenAddressProblem)
        require(problem == null) { "listen address: $problem" }
    }

    public companion object {
        /** Why a tree's ORB could not listen on [address], or null when it can: one of this host's addresses, or `0.0.0.0`. */
        @JvmStatic
        public fun listenAddressProblem(address: String): String? = ListenAddress.problem(address)
    }
}
