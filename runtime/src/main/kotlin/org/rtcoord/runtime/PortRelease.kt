package org.rtcoord.runtime

import java.net.BindException
import java.net.InetSocketAddress
import java.net.ServerSocket
import kotlin.time.Duration
import org.slf4j.LoggerFactory

private val log = LoggerFactory.getLogger("org.rtcoord.runtime.PortRelease")

/**
 * Waits, at most [timeout], until [host]:[port] can be bound again after its listener was closed.
 *
 * The JDK frees a listening socket only once the thread blocked in accept() on it (JacORB's acceptor thread) has woken
 * up, a moment after ServerSocket.close() returned. About half the time the port is still bound when the ORB's shutdown
 * returns, and a restart on it can fail with "Address already in use".
 */
internal fun awaitPortReleased(host: String, port: Int, timeout: Duration) {
    val deadline = System.nanoTime() + timeout.inWholeNanoseconds
    while (true) {
        try {
            ServerSocket().use { probe ->
                probe.reuseAddress = true
                probe.bind(InetSocketAddress(host, port))
            }
            return
        } catch (e: BindException) {
            if (System.nanoTime() > deadline) {
                log.warn("{}:{} is still in use {} after its listener was closed", host, port, timeout)
                return
            }
            Thread.sleep(1)
        }
    }
}
