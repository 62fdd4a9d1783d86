package org.rtcoord.internal.logs

import java.net.InetSocketAddress

/**
 * `host:port`, `[v6]:port` or a bare port (on loopback) as a socket address to listen on.
 *
 * @throws IllegalArgumentException naming [address] and what is wrong with it.
 */
internal fun logInputAddress(address: String): InetSocketAddress {
    val text = address.trim()
    val (host, port) =
        when {
            text.all(Char::isDigit) -> "127.0.0.1" to text
            text.startsWith("[") && "]:" in text -> text.substring(1, text.indexOf("]:")) to text.substringAfter("]:")
            ':' in text -> text.substringBeforeLast(':') to text.substringAfterLast(':')
            else -> throw IllegalArgumentException("log input address '$address': expected HOST:PORT")
        }
    val number = port.toIntOrNull()?.takeIf { it in 0..65535 }
    require(host.isNotEmpty() && number != null) {
        "log input address '$address': expected HOST:PORT with a port from 0 to 65535"
    }
    return InetSocketAddress(host, number)
}
