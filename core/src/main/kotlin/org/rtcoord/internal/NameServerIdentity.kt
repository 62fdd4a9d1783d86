package org.rtcoord.internal

import java.net.InetAddress
import java.net.UnknownHostException

/**
 * Whether two name server addresses (normalised `host:port`) reach the same name server: the same port on hosts that
 * resolve to a common address, every loopback address counting as one. So `localhost:2810`, `127.0.0.1:2810` and a host
 * name that maps to the loopback (Debian's `127.0.1.1`) are one server, as they are one process. Only hosts written
 * differently on the same port are resolved: a tree of name servers on distinct ports never waits for a name lookup. A
 * host that does not resolve is only itself.
 */
internal object NameServerIdentity {
    fun same(first: String, second: String): Boolean {
        if (first == second) return true
        if (first.substringAfterLast(':') != second.substringAfterLast(':')) return false
        val firstAddresses = resolve(first.substringBeforeLast(':')) ?: return false
        val secondAddresses = resolve(second.substringBeforeLast(':')) ?: return false
        return firstAddresses.any { one ->
            secondAddresses.any { other -> one == other || (one.isLoopbackAddress && other.isLoopbackAddress) }
        }
    }

    private fun resolve(host: String): Array<InetAddress>? =
        try {
            InetAddress.getAllByName(host)
        } catch (e: UnknownHostException) {
            null
        }
}
