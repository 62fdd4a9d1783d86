package org.rtcoord.internal

import java.net.BindException
import java.net.DatagramSocket
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.ServerSocket
import java.net.UnknownHostException

/**
 * The address the tree's ORB listens on. Left to itself it is the one this host uses to reach the name server the tree
 * talks to first: the peers that registered there can reach it back, and no other interface is opened. An address the
 * user gives is taken as it is, once it is known to be this host's.
 */
internal object ListenAddress {
    const val LOOPBACK = "127.0.0.1"

    /**
     * The local address of the route to [host] (a name or a literal), loopback when [host] is null, on this host's
     * loopback or cannot be resolved or routed (nothing would answer there anyway).
     */
    fun toward(host: String?): String {
        if (host == null) return LOOPBACK
        val target =
            try {
                InetAddress.getByName(host)
            } catch (e: UnknownHostException) {
                return LOOPBACK
            }
        if (target.isLoopbackAddress) return LOOPBACK
        // Connecting a datagram socket sends nothing: the kernel only picks the route and its source address.
        val local = runCatching {
            DatagramSocket().use {
                it.connect(target, DISCARD_PORT)
                it.localAddress
            }
        }
            .getOrNull()
        return local?.takeUnless { it.isAnyLocalAddress }?.hostAddress ?: LOOPBACK
    }

    /** Why [address] cannot be listened on, or null when it is an address of this host (or the wildcard). */
    fun problem(address: String): String? {
        val resolved =
            try {
                InetAddress.getByName(address)
            } catch (e: UnknownHostException) {
                return "cannot resolve '$address'"
            }
        // Binding is the only test that holds for every local address, 127.0.0.2 included.
        return try {
            ServerSocket().use { it.bind(InetSocketAddress(resolved, 0)) }
            null
        } catch (e: BindException) {
            "$address is not an address of this host"
        }
    }

    private const val DISCARD_PORT = 9
}
