package org.rtcoord.internal.logs

import java.io.IOException
import java.net.BindException
import java.net.DatagramPacket
import java.net.DatagramSocket
import java.net.InetSocketAddress
import java.net.ServerSocket
import java.net.Socket
import java.security.SecureRandom
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CountDownLatch
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicLongArray
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.CompletableJob
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch

/**
 * A Fluentd forward-protocol input: what OpenRTM-aist 2.x components send their log records to (Python's `FluentLogger`
 * through fluent-logger, C++'s `fluentbit_stream` through Fluent Bit), as Fluentd's in_forward accepts it. It listens
 * on [ForwardSettings.address], TCP for events and UDP for out_forward's heartbeats (answered with one zero byte, as
 * in_forward answers them; a TCP heartbeat is a connection that closes, which needs nothing).
 *
 * Every event is handed to [received], in order for each connection, on the connection's thread: [received] must not
 * block. Each sender's mistakes (see [ForwardRefusal]) close its connection, are counted ([refusals]) and told to
 * [refused] with a one-line reason; no other connection notices. A connection holds at most a frame of
 * [ForwardSettings.maxRecordBytes] and the events decoded from it.
 *
 * Its coroutines run in a job of their own, a child of [scope]'s, on I/O threads (reads block: a view of
 * [Dispatchers.IO] keeps many idle senders from starving the rest of the process's I/O). [close] closes every socket,
 * which ends the blocked reads, and waits for the coroutines to end; so does cancelling [scope].
 *
 * Not offered: TLS, user and password authentication (see [SharedKeyHandshake]), in_forward's JSON frames.
 *
 * @throws BindException naming the address when it cannot be listened on, on TCP or UDP.
 */
internal class ForwardInput(
    scope: CoroutineScope,
    private val settings: ForwardSettings,
    private val received: (ForwardEntry) -> Unit,
    private val refused: (InetSocketAddress, ForwardRefusal, String) -> Unit,
) : AutoCloseable {
    private val server = ServerSocket()
    private val heartbeats: DatagramSocket
    private val job: CompletableJob
    private val connections = ConcurrentHashMap.newKeySet<Socket>()
    private val counts = AtomicLongArray(ForwardRefusal.entries.size)
    private val closed = AtomicBoolean()
    private val random = SecureRandom()

    /** The address listened on: the port chosen when port 0 was asked. */
    val address: InetSocketAddress

    init {
        try {
            server.bind(settings.address, BACKLOG)
        } catch (e: IOException) {
            server.close()
            throw BindException("cannot listen for Fluentd's forward protocol on ${settings.address}: ${e.message}")
        }
        address = InetSocketAddress(settings.address.address, server.localPort)
        heartbeats =
            try {
                DatagramSocket(address)
            } catch (e: IOException) {
                server.close()
                throw BindException("cannot listen for Fluentd's UDP heartbeats on $address: ${e.message}")
            }
        // Made once both sockets are bound: an input that failed to bind leaves no job in the scope.
        job = SupervisorJob(scope.coroutineContext[Job])
        val inputScope =
            CoroutineScope(scope.coroutineContext + job + THREADS + CoroutineName("forward input $address"))
        // Cancelling the scope ends what blocks in a socket only by closing the sockets.
        inputScope.launch {
            try {
                awaitCancellation()
            } finally {
                closeSockets()
            }
        }
        inputScope.launch { accept(inputScope) }
        inputScope.launch { answerHeartbeats() }
    }

    /** The refusals so far, by reason, zeros included. */
    fun refusals(): Map<ForwardRefusal, Long> = ForwardRefusal.entries.associateWith { counts[it.ordinal] }

    /**
     * Closes the listener and every connection, and waits for the input's coroutines to end, unless called from
     * [received] or [refused] (their own coroutine cannot end under them). Idempotent.
     */
    override fun close() {
        if (closed.compareAndSet(false, true)) {
            closeSockets()
            job.cancel()
        }
        if (inCallback.get() != true) {
            val ended = CountDownLatch(1)
            job.invokeOnCompletion { ended.countDown() }
            // Bounded: a socket closed ends its read at once; the bound only keeps a stuck JVM from hanging close.
            ended.await(CLOSE_WAIT_SECONDS, TimeUnit.SECONDS)
        }
    }

    private fun closeSockets() {
        server.close()
        heartbeats.close()
        connections.forEach(Socket::close)
    }

    private suspend fun accept(scope: CoroutineScope) {
        while (scope.isActive) {
            val socket =
                try {
                    server.accept()
                } catch (e: IOException) {
                    if (server.isClosed) return
                    // Out of descriptors, most likely: let connections end before trying again.
                    delay(ACCEPT_RETRY)
                    continue
                }
            connections += socket
            if (closed.get()) socket.close()
            // Started atomically: a connection accepted as the input closes still reaches its finally, which closes it.
            scope.launch(start = CoroutineStart.ATOMIC) {
                try {
                    serve(socket)
                } finally {
                    socket.close()
                    connections -= socket
                }
            }
        }
    }

    private suspend fun serve(socket: Socket) {
        val sender = socket.remoteSocketAddress as InetSocketAddress
        val handshake = settings.sharedKey?.let { SharedKeyHandshake(it, settings.selfHostname, random) }
        ForwardConnection(
                socket,
                settings,
                handshake,
                received = { entry -> callback { received(entry) } },
                refused = { refusal, reason ->
                    counts.incrementAndGet(refusal.ordinal)
                    callback { refused(sender, refusal, reason) }
                },
            )
            .serve()
    }

    private inline fun callback(call: () -> Unit) {
        inCallback.set(true)
        try {
            call()
        } finally {
            inCallback.remove()
        }
    }

    private fun answerHeartbeats() {
        val packet = DatagramPacket(ByteArray(HEARTBEAT_BYTES), HEARTBEAT_BYTES)
        while (true) {
            try {
                packet.setLength(HEARTBEAT_BYTES)
                heartbeats.receive(packet)
                heartbeats.send(DatagramPacket(HEARTBEAT_ANSWER, HEARTBEAT_ANSWER.size, packet.socketAddress))
            } catch (e: IOException) {
                if (heartbeats.isClosed) return
                // A send refused by the network (the sender gone) concerns that sender only.
            }
        }
    }

    private companion object {
        const val BACKLOG = 128
        const val HEARTBEAT_BYTES = 128
        const val CLOSE_WAIT_SECONDS = 10L
        val ACCEPT_RETRY = 100.milliseconds
        val HEARTBEAT_ANSWER = byteArrayOf(0)

        /**
         * Blocking reads hold a thread each: a view of the I/O pool, whose threads are not counted against the pool's
         * own 64, so that many quiet senders take none of them.
         */
        val THREADS = Dispatchers.IO.limitedParallelism(MAX_BLOCKED_THREADS)

        const val MAX_BLOCKED_THREADS = 512

        /** Set on a thread while it runs a callback: [close] called there must not wait for itself. */
        val inCallback = ThreadLocal<Boolean>()
    }
}
