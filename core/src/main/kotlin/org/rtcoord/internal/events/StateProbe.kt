package org.rtcoord.internal.events

import RTC.ExecutionContext
import RTC.LifeCycleStateHelper
import RTC.LightweightRTObjectHelper
import RTC.RTObject
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.atomic.AtomicIntegerArray
import org.rtcoord.ComponentSnapshot
import org.rtcoord.LifeCycle
import org.rtcoord.internal.AsyncRequests
import org.rtcoord.internal.toLifeCycle

/**
 * The poll read of a component whose registrations want its states alone, made without its monitor: a tick sends
 * `get_component_state` to each of its contexts ([AsyncRequests]) and, when the replies find the states the monitor
 * expects ([expect]), ends there, on the ORB's reader thread, waking nothing. Polling a thousand components, that is
 * nearly every read. Anything else goes to the monitor, whose own read or reconciliation decides: states that differ
 * ([Outcome.Changed]), a request that failed or whose reply has not come by the component's next tick
 * ([Outcome.Unsettled]).
 *
 * One read at a time (its poll schedule ticks a component only once the previous tick is done).
 */
internal class StateProbe(
    private val requests: AsyncRequests,
    private val component: RTObject,
    /**
     * The stamp of a read of the component's states starting now (see [org.rtcoord.internal.ComponentObject.stamp]).
     */
    private val nextStamp: () -> Long,
    private val answered: () -> Unit,
    private val handOver: (Outcome) -> Unit,
) {
    /** What the monitor believes: each context's [states], as of its read number [epoch]. */
    class Expectation(val contexts: List<Pair<Int, ExecutionContext>>, val states: List<LifeCycle>, val epoch: Long) {
        companion object {
            /**
             * The states of [snapshot], read number [epoch], in [contexts] by handle; null when it is in none, or in
             * one not among them.
             */
            fun of(snapshot: ComponentSnapshot, contexts: Map<Int, ExecutionContext>, epoch: Long): Expectation? {
                if (snapshot.contexts.isEmpty() || snapshot.contexts.any { it.handle !in contexts }) return null
                return Expectation(
                    snapshot.contexts.map { it.handle to contexts.getValue(it.handle) },
                    snapshot.contexts.map { it.state },
                    epoch,
                )
            }
        }
    }

    /** How a probe the monitor must finish ended; [done] tells the poll schedule once it has. */
    sealed class Outcome(val done: () -> Unit) {
        /**
         * The replies found [states] (by context handle), other than expected as of read [epoch], in the read stamped
         * [stamp].
         */
        class Changed(val states: Map<Int, LifeCycle>, val epoch: Long, val stamp: Long, done: () -> Unit) :
            Outcome(done)

        /** No answer to go by: the monitor reads the component itself. */
        class Unsettled(done: () -> Unit) : Outcome(done)
    }

    private inner class Round(val expectation: Expectation, val done: () -> Unit) {
        val stamp = nextStamp()
        val ids =
            AtomicIntegerArray(expectation.contexts.size).also { ids -> repeat(ids.length()) { ids[it] = NO_REQUEST } }
        val states = arrayOfNulls<LifeCycle>(expectation.contexts.size)
        val remaining = AtomicInteger(expectation.contexts.size)
        val finished = AtomicBoolean()
    }

    @Volatile private var expectation: Expectation? = null
    @Volatile private var round: Round? = null

    /**
     * Where the replies for each context go: one handler per context, so a reply is told apart by its request id on
     * that context's connection.
     */
    private inner class ContextReplies(val index: Int) {
        val replies = requests.Replies({ id, result -> received(this, id, result) }, { failed(this) })
    }

    @Volatile private var channels: List<ContextReplies> = emptyList()
    @Volatile private var closed = false

    /** Probes expect [expectation] from now on; none are made while it is null (the monitor takes the ticks). */
    fun expect(expectation: Expectation?) {
        this.expectation = expectation
    }

    /** Sends the read of one tick; returns false, sending nothing, when the monitor must take this tick. */
    fun send(done: () -> Unit): Boolean {
        val expected = expectation?.takeUnless { closed } ?: return false
        val round = Round(expected, done)
        this.round = round
        val channels = channelsFor(expected.contexts.size)
        try {
            expected.contexts.forEachIndexed { index, (_, context) ->
                val request = channels[index].replies.request(context, "get_component_state")
                LightweightRTObjectHelper.write(request.arguments, component)
                round.ids[index] = request.id
                request.send()
            }
        } catch (e: Exception) {
            unsettle(round)
        }
        return true
    }

    /** The read sent at the previous tick is still unanswered: the monitor reads instead. */
    fun late() {
        round?.let(::unsettle)
    }

    /** Stops probing; handlers leave the ORB once their replies are in. */
    fun close() {
        closed = true
        expectation = null
        round?.let(::unsettle)
        retire()
    }

    private fun channelsFor(count: Int): List<ContextReplies> {
        if (channels.size != count) {
            retire()
            channels = List(count, ::ContextReplies)
        }
        return channels
    }

    /** Closes the channels: replies still to come go to handlers no round listens to. */
    private fun retire() {
        channels.forEach { it.replies.close() }
        channels = emptyList()
    }

    private fun received(channel: ContextReplies, id: Int, result: org.omg.CORBA.portable.InputStream) {
        val round = round?.takeIf { channels.getOrNull(channel.index) === channel } ?: return
        // A reply to a request given up on: a later round's requests have other ids.
        if (round.ids[channel.index] != id) return
        round.states[channel.index] = LifeCycleStateHelper.read(result).toLifeCycle()
        if (round.remaining.decrementAndGet() == 0) finish(round)
    }

    private fun failed(channel: ContextReplies) {
        round?.takeIf { channels.getOrNull(channel.index) === channel }?.let(::unsettle)
    }

    private fun finish(round: Round) {
        if (!round.finished.compareAndSet(false, true)) return
        this.round = null
        val expected = round.expectation
        if (round.states.indices.all { round.states[it] == expected.states[it] }) {
            answered()
            round.done()
            return
        }
        val states = expected.contexts.mapIndexed { index, (handle, _) -> handle to round.states[index]!! }.toMap()
        handOver(Outcome.Changed(states, expected.epoch, round.stamp, round.done))
    }

    /**
     * Gives [round] up to the monitor. Its channels are retired if a reply may still come: on another connection after
     * a reconnection, a request id may be used again.
     */
    private fun unsettle(round: Round) {
        if (!round.finished.compareAndSet(false, true)) return
        if (this.round === round) this.round = null
        if (round.remaining.get() > 0) retire()
        handOver(Outcome.Unsettled(round.done))
    }

    private companion object {
        /** No request sent yet for a context: no reply id matches it. JacORB's ids are non-negative. */
        const val NO_REQUEST = -1
    }
}
