package org.rtcoord.internal

import java.io.InputStream
import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.util.concurrent.ConcurrentHashMap
import kotlin.time.Duration
import kotlin.time.TimeSource
import org.jacorb.orb.factory.ServerSocketFactory

/**
 * Every connection peers opened to the tree's ORB, and how far its reader has got in each: the ORB's server socket
 * factory (JacORB's `jacorb.net.server_socket_factory`, which JacORB makes one of per ORB).
 *
 * It answers one question ([allTaken]): has the ORB taken every byte that has reached this host for it so far? A
 * component's hints come on its own connection, read by a thread of their own, while the answers to the tree's reads
 * come on another. Under load, that thread may not run for milliseconds after a read it overtook came back, so what the
 * hints said meanwhile (an abort's ERROR, once a reset made the component INACTIVE again) is in this host's socket,
 * unread, while threads woken later run on.
 */
internal class InboundConnections : ServerSocketFactory {
    private val connections: MutableSet<InboundConnection> = ConcurrentHashMap.newKeySet()
    private val accepted: MutableSet<Accepted> = ConcurrentHashMap.newKeySet()
    /** [closeAll] was called: a peer connecting again is hung up on at once. */
    @Volatile private var refusing = false

    override fun createServerSocket(port: Int): ServerSocket = Listening(port, 0, null)

    override fun createServerSocket(port: Int, backlog: Int): ServerSocket = Listening(port, backlog, null)

    override fun createServerSocket(port: Int, backlog: Int, ifAddress: InetAddress?): ServerSocket =
        Listening(port, backlog, ifAddress)

    /**
     * Whether the ORB has handed every message its connections hold now, read or not, to its POAs. If not, [later] runs
     * once it has, on the ORB's thread that handed over the last of them, so it must not block; a connection that
     * closes meanwhile counts as done.
     */
    fun allTaken(later: Runnable): Boolean {
        val targets = connections.mapNotNull { connection -> connection.target()?.let { connection to it } }
        if (targets.isEmpty()) return true
        val barrier = InboundConnection.Barrier(targets.size, later)
        for ((connection, target) in targets) connection.await(target, barrier)
        return barrier.setUp()
    }

    /**
     * Closes every connection peers opened, and any they open from now on, so that nothing more comes in; waits until
     * each one's reader has found it closed, [timeout] at most for all of them.
     */
    fun closeAll(timeout: Duration) {
        refusing = true
        val closing = accepted.toList()
        val readers = closing.mapNotNull { it.reader() }
        closing.forEach { runCatching { it.close() } }
        val deadline = TimeSource.Monotonic.markNow() + timeout
        for (reader in readers) if (!reader.awaitReaderGone(-deadline.elapsedNow())) return
    }

    /** A listening socket whose every accepted connection is counted, until [closeAll] refuses them. */
    private inner class Listening(port: Int, backlog: Int, address: InetAddress?) :
        ServerSocket(port, backlog, address) {
        override fun accept(): Socket {
            while (true) {
                val socket = Accepted()
                implAccept(socket)
                // Added before the flag is read, as closeAll sets the flag before it lists: one of the two closes it.
                accepted += socket
                if (!refusing) return socket
                socket.close()
            }
        }
    }

    /** One accepted connection, whose input the ORB reads through an [InboundConnection]. */
    private inner class Accepted : Socket() {
        private var counted: InboundConnection? = null

        /** What the ORB reads this connection through, once it has started to. */
        @Synchronized fun reader(): InboundConnection? = counted

        @Synchronized
        override fun getInputStream(): InputStream =
            counted
                ?: InboundConnection(super.getInputStream()).also {
                    counted = it
                    connections += it
                }

        override fun close() {
            try {
                super.close()
            } finally {
                accepted -= this
                synchronized(this) { counted }
                    ?.let {
                        it.release()
                        connections -= it
                    }
            }
        }
    }
}
