package org.rtcoord.internal.logs

import java.io.IOException
import java.net.BindException
import java.net.InetSocketAddress
import java.net.StandardSocketOptions
import java.nio.ByteBuffer
import java.nio.channels.DatagramChannel
import java.nio.channels.SelectionKey
import java.nio.channels.Selector
import java.nio.channels.ServerSocketChannel
import java.security.SecureRandom
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
import kotlinx.coroutines.currentCoroutineContext
import kotlinx.coroutines.delay
import kotlinx.coroutines.ensureActive
import kotlinx.coroutines.launch
import org.slf4j.LoggerFactory

/**
 * A Fluentd forward-protocol input: what OpenRTM-aist 2.x components send their log records to (Python's `FluentLogger`
 * through fluent-logger, C++'s `fluentbit_stream` through Fluent Bit), as Fluentd's in_forward accepts it. It listens
 * on [ForwardSettings.address], TCP for events and UDP for out_forward's heartbeats (answered with one zero byte, as
 * in_forward answers them; a TCP heartbeat is a connection that closes, which needs nothing).
 *
 * Every event is handed to [received], in order for each connection: [received] must not block. Each sender's mistakes
 * (see [ForwardRefusal]) close its connection, are counted ([refusals]) and told to [refused] with a one-line reason;
 * no other connection notices. A connection holds at most a frame of [ForwardSettings.maxRecordBytes] and the events
 * decoded from it.
 *
 * One coroutine serves every socket through one selector, on an I/O thread while it waits in a select. After a round
 * that read something it rests [REST] before selecting again, unless a read filled its chunk: a record that comes alone
 * is handed on at once, and a stream from many senders (a Message-mode sender writes each record apart) is read a round
 * of many records at a time, not a wake-up per record. Its job is a child of [scope]'s; [close] ends it, and so does
 * cancelling [scope], either closing every socket.
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
    private val selector = Selector.open()
    private val server = ServerSocketChannel.open()
    private val heartbeats = DatagramChannel.open()
    private val job: CompletableJob
    private val counts = AtomicLongArray(ForwardRefusal.entries.size)
    private val closed = AtomicBoolean()
    private val random = SecureRandom()
    private var scratchBuffer = ByteArray(0)
    private val heartbeat = ByteBuffer.allocate(HEARTBEAT_BYTES)

    /** When accepting may be tried again after it failed (System.nanoTime); null while accepting. */
    private var acceptResumes: Long? = null

    /** The address listened on: the port chosen when port 0 was asked. */
    val address: InetSocketAddress

    init {
        try {
            server.bind(settings.address, BACKLOG)
        } catch (e: IOException) {
            closeChannels()
            throw BindException("cannot listen for Fluentd's forward protocol on ${settings.address}: ${e.message}")
        }
        address = InetSocketAddress(settings.address.address, (server.localAddress as InetSocketAddress).port)
        try {
            heartbeats.bind(address)
        } catch (e: IOException) {
            closeChannels()
            throw BindException("cannot listen for Fluentd's UDP heartbeats on $address: ${e.message}")
        }
        server.configureBlocking(false).register(selector, SelectionKey.OP_ACCEPT)
        heartbeats.configureBlocking(false).register(selector, SelectionKey.OP_READ)
        // Made once both sockets are bound: an input that failed to bind leaves no job in the scope.
        job = SupervisorJob(scope.coroutineContext[Job])
        val inputScope =
            CoroutineScope(scope.coroutineContext + job + Dispatchers.IO + CoroutineName("forward input $address"))
        // A select blocks its thread: cancelling the scope ends it by waking the selector.
        inputScope.launch {
            try {
                awaitCancellation()
            } finally {
                selector.wakeup()
            }
        }
        // Started atomically: however early the scope is cancelled, the sockets are closed on the way out.
        inputScope.launch(start = CoroutineStart.ATOMIC) {
            try {
                serve()
            } finally {
                closeChannels()
            }
        }
    }

    /** The refusals so far, by reason, zeros included. */
    fun refusals(): Map<ForwardRefusal, Long> = ForwardRefusal.entries.associateWith { counts[it.ordinal] }

    /**
     * Closes the listener and every connection, and waits for the input's coroutines to end, unless called from
     * [received] or [refused] (their coroutine cannot end under them). Idempotent.
     */
    override fun close() {
        if (closed.compareAndSet(false, true)) {
            job.cancel()
            selector.wakeup()
        }
        if (inCallback.get() != true) {
            val ended = CountDownLatch(1)
            job.invokeOnCompletion { ended.countDown() }
            // Bounded: a woken select returns at once; the bound only keeps a stuck JVM from hanging close.
            ended.await(CLOSE_WAIT_SECONDS, TimeUnit.SECONDS)
        }
    }

    /** Selects and serves what is ready, round after round, until the scope is cancelled or the input closed. */
    private suspend fun serve() {
        while (true) {
            currentCoroutineContext().ensureActive()
            selector.select(selectTimeoutMillis())
            currentCoroutineContext().ensureActive()
            var read = false
            var more = false
            inCallback.set(true)
            try {
                val ready = selector.selectedKeys().iterator()
                while (ready.hasNext()) {
                    val key = ready.next()
                    ready.remove()
                    if (!key.isValid) continue
                    when (val attachment = key.attachment()) {
                        is ForwardConnection -> {
                            if (key.isWritable) serveSafely(attachment) { it.writable() }
                            if (key.isValid && key.isReadable) {
                                read = true
                                serveSafely(attachment) { more = it.readable(::scratch) || more }
                            }
                        }
                        else ->
                            when (key.channel()) {
                                server -> accept()
                                heartbeats -> answerHeartbeats()
                            }
                    }
                }
                closeStalledFrames()
            } finally {
                inCallback.remove()
            }
            if (read && !more) delay(REST)
        }
    }

    /** How long the next select may wait: until the first frame deadline, or accepting resumes; 0 is for ever. */
    private fun selectTimeoutMillis(): Long {
        val now = System.nanoTime()
        acceptResumes?.let {
            if (now - it >= 0) {
                acceptResumes = null
                server.keyFor(selector).interestOps(SelectionKey.OP_ACCEPT)
            }
        }
        var first = acceptResumes
        for (key in selector.keys()) {
            val deadline = (key.attachment() as? ForwardConnection)?.frameDeadline() ?: continue
            if (first == null || deadline - first < 0) first = deadline
        }
        return first?.let { TimeUnit.NANOSECONDS.toMillis(it - now).coerceAtLeast(1) } ?: 0
    }

    private fun closeStalledFrames() {
        val now = System.nanoTime()
        for (key in selector.keys()) (key.attachment() as? ForwardConnection)?.closeIfStalled(now)
    }

    /**
     * Serves [connection] with [action]; a failure of [received] or [refused] (theirs, not the sender's) closes that
     * connection, said, and nothing else.
     */
    private inline fun serveSafely(connection: ForwardConnection, action: (ForwardConnection) -> Unit) {
        try {
            action(connection)
        } catch (e: RuntimeException) {
            connection.close()
            logger.error("forward input $address: closed ${connection.sender}'s connection after a failure", e)
        }
    }

    /** A buffer of at least [size] bytes, shared by the connections: only one is read at a time. */
    private fun scratch(size: Int): ByteArray {
        if (scratchBuffer.size < size) scratchBuffer = ByteArray(size)
        return scratchBuffer
    }

    private fun accept() {
        while (true) {
            val channel =
                try {
                    server.accept() ?: return
                } catch (e: IOException) {
                    // Out of descriptors, most likely: let connections end before trying again.
                    server.keyFor(selector).interestOps(0)
                    acceptResumes = System.nanoTime() + ACCEPT_RETRY.inWholeNanoseconds
                    return
                }
            try {
                channel.configureBlocking(false)
                channel.setOption(StandardSocketOptions.TCP_NODELAY, true)
                val key = channel.register(selector, SelectionKey.OP_READ)
                val connection =
                    ForwardConnection(
                        key,
                        settings,
                        settings.sharedKey?.let { SharedKeyHandshake(it, settings.selfHostname, random) },
                        received,
                        ::refusedFrom,
                    )
                key.attach(connection)
                connection.start()
            } catch (e: IOException) {
                // Gone before it was served: nothing of it to keep.
                channel.close()
            }
        }
    }

    private fun refusedFrom(sender: InetSocketAddress, refusal: ForwardRefusal, reason: String) {
        counts.incrementAndGet(refusal.ordinal)
        refused(sender, refusal, reason)
    }

    private fun answerHeartbeats() {
        while (true) {
            heartbeat.clear()
            val from =
                try {
                    heartbeats.receive(heartbeat) ?: return
                } catch (e: IOException) {
                    return
                }
            try {
                heartbeats.send(ByteBuffer.wrap(HEARTBEAT_ANSWER), from)
            } catch (e: IOException) {
                // A send refused by the network (the sender gone) concerns that sender only.
            }
        }
    }

    private fun closeChannels() {
        if (selector.isOpen) {
            for (key in selector.keys()) key.channel().close()
            selector.close()
        }
        server.close()
        heartbeats.close()
    }

    private companion object {
        const val BACKLOG = 128
        const val HEARTBEAT_BYTES = 128
        const val CLOSE_WAIT_SECONDS = 10L
        val ACCEPT_RETRY = 100.milliseconds
        val HEARTBEAT_ANSWER = byteArrayOf(0)

        /**
         * How long the selector rests after a round that read something: the most a record in a stream waits for it,
         * and what lets each sender's records gather for one read. A read costs a system call whatever it carries, 10
         * to 15 microseconds on the 2-core machine here: at 10,000 records a second from 100 senders, 5 ms meant 20,000
         * reads a second, 100 ms means 1,000. A rule on log records looks at seconds, not tenths of one.
         */
        val REST = 100.milliseconds

        val logger = LoggerFactory.getLogger(ForwardInput::class.java)

        /**
         * Set on the input's thread while it serves a round: [close] called from a callback must not wait for itself.
         */
        val inCallback = ThreadLocal<Boolean>()
    }
}
