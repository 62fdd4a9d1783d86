package org.rtcoord.runtime

import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.util.concurrent.ConcurrentHashMap
import org.jacorb.orb.factory.ServerSocketFactory

/**
 * The listening sockets of one runtime ORB (JacORB's `jacorb.net.server_socket_factory`), which keep the connections
 * they accept so that [end] can close them all, as a process's exit does.
 *
 * JacORB's shutdown closes a server connection only when no request is pending on it. One that arrived during the
 * shutdown, or that a hung component holds, keeps it open; a client goes on sending on it whatever it sends to that
 * address, and a naming service restarted on the same port never hears from that client: the dead ORB answers in its
 * place with OBJECT_NOT_EXIST.
 */
internal class ServerConnections : ServerSocketFactory {
    private val accepted = ConcurrentHashMap.newKeySet<Socket>()
    @Volatile private var ended = false

    override fun createServerSocket(port: Int): ServerSocket = Listening(port, 0, null)

    override fun createServerSocket(port: Int, backlog: Int): ServerSocket = Listening(port, backlog, null)

    override fun createServerSocket(port: Int, backlog: Int, ifAddress: InetAddress?): ServerSocket =
        Listening(port, backlog, ifAddress)

    /** Closes every accepted connection, and any accepted from now on. */
    fun end() {
        ended = true
        for (socket in accepted) socket.close()
    }

    private inner class Listening(port: Int, backlog: Int, address: InetAddress?) :
        ServerSocket(port, backlog, address) {
        override fun accept(): Socket {
            val socket = Accepted()
            implAccept(socket)
            accepted += socket
            // end() may have run between the accept and the line above.
            if (ended) socket.close()
            return socket
        }
    }

    private inner class Accepted : Socket() {
        override fun close() {
            accepted -= this
            super.close()
        }
    }
}
