package org.rtcoord.internal.logs

import java.net.InetSocketAddress
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicLong
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.channels.BufferOverflow
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import kotlinx.coroutines.yield
import org.rtcoord.LogInput
import org.rtcoord.LogRecord
import org.rtcoord.Node
import org.rtcoord.RootNode
import org.rtcoord.RtcException
import org.rtcoord.internal.TreeCore
import org.rtcoord.internal.componentsFound
import org.rtcoord.internal.events.EventSink
import org.slf4j.LoggerFactory

/**
 * The tree's log records: its inputs, who each record is from ([LogSenders]), and the registrations that hear them. A
 * record is published through the tree's model as every event is, numbered, so that it sits in `follow`'s stream and a
 * recording in its place among the state changes. Hearing records takes no watching: a registration for records alone
 * attaches no observer and polls nothing.
 */
internal class LogRecords(private val core: TreeCore) {
    private class Registration(val sink: EventSink, val covers: (LogRecord) -> Boolean)

    private val registrations = CopyOnWriteArrayList<Registration>()
    private val inputs = CopyOnWriteArrayList<AutoCloseable>()
    private val senders = LogSenders({ core.nameServers() }, core.clock::now)
    /** When the listings were last walked for a sender no listing showed; [Long.MIN_VALUE]: never. */
    private var relisted = Long.MIN_VALUE
    private val relisting = Mutex()

    /** Records dropped, oldest first, because a handler of records alone fell [HANDLER_QUEUE] behind. */
    private val handlerDrops = AtomicLong()
    /** When a slow handler's drops were last said; [Long.MIN_VALUE]: never. */
    private val dropsSaid = AtomicLong(Long.MIN_VALUE)

    /** Counts a record a slow handler lost, and says so (see [sayDrops]). */
    fun droppedByHandler() {
        val count = handlerDrops.incrementAndGet()
        sayDrops {
            "a handler of log records is too slow for them: the oldest of the $HANDLER_QUEUE waiting for it are dropped ($count so far)"
        }
    }

    /**
     * Says [what] was dropped, at most once a minute for the tree's inputs and handlers together: drops come in floods.
     */
    private inline fun sayDrops(what: () -> String) {
        val now = core.clock.now()
        val said = dropsSaid.get()
        if ((said == Long.MIN_VALUE || now - said >= SAY_DROPS_MILLIS) && dropsSaid.compareAndSet(said, now)) {
            LoggerFactory.getLogger("org.rtcoord.logs").warn(what())
        }
    }

    /** Hands [sink] the records from [target] or from below it; returns what ends that. */
    fun add(sink: EventSink, target: Node): () -> Unit {
        val registration = Registration(sink, logCoverage(target, core.clock::now))
        registrations += registration
        return { registrations -= registration }
    }

    /** Starts an input on [address] whose records that match no listed sender come from [root]. */
    fun listen(address: InetSocketAddress, sharedKey: String?, root: RootNode): LogInput {
        val input = Input(address, sharedKey, root)
        inputs += input
        return input
    }

    fun close() {
        inputs.forEach(AutoCloseable::close)
    }

    /**
     * Who [entry] is from: a listed sender, else (the listings walked again, at most once every [RELIST_MILLIS]: a
     * component created since, or a tree that listed nothing yet) one found then, else null.
     */
    private suspend fun senderOf(entry: ForwardEntry): Node? {
        val (logger, manager) = senderNamesOf(entry)
        senders.senderOf(logger, manager)?.let {
            return it
        }
        relisting.withLock {
            val now = core.clock.now()
            if (relisted != Long.MIN_VALUE && now - relisted < RELIST_MILLIS) return null
            relisted = now
            // Profiles too, each read once: a standalone Python component's is the only place its manager's name is.
            val unread = componentsFound(core.nameServers()).filter { it.component.snapshot.value == null }
            coroutineScope {
                unread.forEach { node ->
                    launch {
                        try {
                            node.snapshot()
                        } catch (e: RtcException) {
                            // Unreachable now: the sender is not this one, or is found at a later walk.
                        }
                    }
                }
            }
            senders.forget()
        }
        return senders.senderOf(logger, manager)
    }

    private inner class Input(listen: InetSocketAddress, sharedKey: String?, private val root: RootNode) : LogInput {
        private val count = AtomicLong()
        private val dropped = AtomicLong()
        /**
         * Records waiting for their sender to be found, in the order they came; the oldest dropped, and counted, when
         * more come than can wait, so that a flood costs no more than this much memory.
         */
        // Named as asked (the port may be 0): the input may refuse a sender before it says which port it took.
        private val refusals = LogRefusals("${listen.hostString}:${listen.port}", core.clock::now)
        private val pending =
            Channel<ForwardEntry>(PENDING, BufferOverflow.DROP_OLDEST) {
                val count = dropped.incrementAndGet()
                if (!closed)
                    sayDrops {
                        "log input $address receives records faster than they are published: the oldest of the $PENDING waiting are dropped ($count so far)"
                    }
            }
        @Volatile private var closed = false
        private val forward =
            ForwardInput(
                core.scope,
                ForwardSettings(listen, sharedKey),
                ::received,
                { sender, refusal, reason -> refusals.refused(sender, refusal, reason) },
            )
        /**
         * Started once the input listens, so that an address it cannot take leaves nothing running. Publishes what
         * waits, then rests [LINGER] before taking more: a record that comes alone goes at once, and a stream wakes
         * this coroutine, and the handlers' after it, once a linger, not once a record (at 10,000 records a second, the
         * wake-ups, not the records, were most of the cost).
         */
        private val publishing =
            core.scope.launch {
                val batch = ArrayList<LogRecord>()
                for (first in pending) {
                    var entry: ForwardEntry? = first
                    while (entry != null) {
                        batch += logRecordOf(entry, senderOf(entry) ?: root)
                        entry = if (batch.size < MAX_BATCH) pending.tryReceive().getOrNull() else null
                    }
                    core.model.publish(batch) { event ->
                        registrations.forEach { if (it.covers(event as LogRecord)) it.sink.offer(event) }
                    }
                    val full = batch.size == MAX_BATCH
                    batch.clear()
                    // A full batch leaves more waiting: rest only once the stream is taken in.
                    if (full) yield() else delay(LINGER)
                }
            }

        override val host: String = forward.address.hostString
        override val port: Int = forward.address.port

        override val received: Long
            get() = count.get()

        override fun refusals(): Map<String, Long> = buildMap {
            forward.refusals().forEach { (refusal, count) -> put(refusal.id, count) }
            mapOf(DROPPED to dropped.get(), SLOW_HANDLER to handlerDrops.get()).forEach { (why, count) ->
                if (count > 0) put(why, count)
            }
        }

        private fun received(entry: ForwardEntry) {
            count.incrementAndGet()
            pending.trySend(entry)
        }

        override fun close() {
            closed = true
            forward.close()
            pending.close()
            publishing.cancel()
            inputs -= this
        }
    }

    companion object {
        /** How many records may wait for a handler of records alone before the oldest are dropped. */
        const val HANDLER_QUEUE = 10_000

        /** What [LogInput.refusals] calls records a handler too slow for them lost (the tree's, for each input). */
        private const val SLOW_HANDLER = "slow-handler"

        /** How often at most a slow handler's drops are said. */
        private const val SAY_DROPS_MILLIS = 60_000L

        /** How many records may wait for their sender to be found before the oldest are dropped. */
        private const val PENDING = 10_000

        /** What [LogInput.refusals] calls records dropped because more came than could wait. */
        private const val DROPPED = "dropped"

        /** The most records published at once: the model's lock is held while a batch is handed out. */
        private const val MAX_BATCH = 1000

        /** How long the publisher rests after a batch: the most a record in a stream waits for it. */
        private val LINGER = 5.milliseconds

        /** How often at most the listings are walked again for a sender they do not show. */
        private const val RELIST_MILLIS = 5_000L
    }
}
