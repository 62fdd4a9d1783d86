package org.rtcoord.internal.events

import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicBoolean
import kotlin.coroutines.CoroutineContext
import kotlin.coroutines.EmptyCoroutineContext
import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.DurationUnit
import kotlin.time.TimeMark
import kotlin.time.TimeSource
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Semaphore

/**
 * Every component of a tree polled at one [period], on one schedule: each round reads every member once, their reads
 * spread over the period (member i of n at i/n of it; those due within a [slice] of each other leave together, one
 * wake-up for several reads rather than one each). A member's read is a [Member.probe] when it can make one (no thread
 * waits for the reply; at most [PROBES_IN_FLIGHT] pending), else a [Member.tick] (at most [inFlight] pending: each
 * holds a thread). When the reads cannot keep up, a round simply takes longer: every member is then read at the same,
 * lower rate, and [slow] is told once (after [SLOW_ROUNDS] slow rounds in a row) what that rate is. Ticks a round could
 * not serve in time count as [missed] (a member whose previous read still waits, a hung component, is passed over in
 * that round rather than holding the others up, and told it is [Member.late]). Its rounds run in [context]: on the
 * dispatcher the members read on, a tick and its read pass from one to the other without waking a thread.
 */
internal class PollSchedule(
    scope: CoroutineScope,
    val period: Duration,
    private val inFlight: Int,
    private val missed: (Long) -> Unit,
    private val slow: (members: Int, achieved: Duration) -> Unit,
    private val time: TimeSource = TimeSource.Monotonic,
    context: CoroutineContext = EmptyCoroutineContext,
) {
    /** One polled component. Each read it is asked for calls `done` once it has ended (or failed). */
    fun interface Member {
        /** Reads the member. */
        fun tick(done: () -> Unit)

        /**
         * Sends a read whose reply no thread waits for, if the member can now; false when it cannot, and [tick] is
         * asked instead.
         */
        fun probe(done: () -> Unit): Boolean = false

        /** Its turn came while its previous read was still pending. */
        fun late() {}
    }

    private class Slot(val member: Member) {
        val busy = AtomicBoolean()
    }

    private val slots = CopyOnWriteArrayList<Slot>()
    private val joined = Channel<Unit>(Channel.CONFLATED)
    private val permits = Semaphore(inFlight)
    private val probes = Semaphore(PROBES_IN_FLIGHT)
    private val slice = (period / SLICES).coerceAtMost(MAX_SLICE)
    private var warned = false
    private var overdue = 0.0

    /** Rounds in a row that overran with as many members, and how long they took together. */
    private var slowRounds = 0
    private var slowTime = Duration.ZERO
    private var lastMembers = 0

    private val rounds: Job =
        scope.launch(context) {
            val origin = time.markNow()
            var due = Duration.ZERO
            while (isActive) {
                // A copy of the array as it is (toList reads a one-element list's element after its size).
                val members = ArrayList(slots)
                if (members.isEmpty()) {
                    joined.receive()
                    due = origin.elapsedNow()
                    continue
                }
                due = round(members, origin, due)
            }
        }

    /** Adds [member]; it is read from the next round on. */
    fun add(member: Member) {
        slots += Slot(member)
        joined.trySend(Unit)
    }

    /** Removes [member]; returns whether none is left (the owner then [stop]s the schedule). */
    fun remove(member: Member): Boolean {
        slots.removeAll { it.member === member }
        return slots.isEmpty()
    }

    fun stop() {
        rounds.cancel()
    }

    /**
     * Reads every member once, spread over the period that begins [due] after [origin]; returns when the next round is
     * due. Rounds keep to one timeline: a round that starts late catches up, and only a schedule a whole period behind
     * gives up the ticks it owes, and goes on from now.
     */
    private suspend fun round(members: List<Slot>, origin: TimeMark, due: Duration): Duration {
        val start = origin.elapsedNow()
        var passedOver = 0L
        members.forEachIndexed { index, slot ->
            val wait = due + period * index.toDouble() / members.size - origin.elapsedNow()
            if (wait > slice) delay(wait)
            // Its previous read still waits (a hung component): this round goes on without it.
            if (!slot.busy.compareAndSet(false, true)) {
                passedOver++
                slot.member.late()
                return@forEachIndexed
            }
            read(slot)
        }
        var next = due + period
        delay(next - origin.elapsedNow())
        val behind = origin.elapsedNow() - next
        if (behind >= period) {
            // A period and a half behind: one and a half ticks of every member were never served.
            overdue += members.size * (behind / period)
            next = origin.elapsedNow()
        }
        val late = overdue.toLong()
        overdue -= late
        if (late + passedOver > 0) missed(late + passedOver)
        noteSpeed(members.size, origin.elapsedNow() - start)
        return next
    }

    /** Says once that the schedule cannot keep up, when rounds of as many members keep taking [took] or longer. */
    private fun noteSpeed(members: Int, took: Duration) {
        // Only a schedule that stays slow with the same members says so: not one still being filled.
        if (took <= period * SLOW || members != lastMembers) {
            lastMembers = members
            slowRounds = 0
            slowTime = Duration.ZERO
            return
        }
        slowRounds++
        slowTime += took
        if (!warned && slowRounds == SLOW_ROUNDS) {
            warned = true
            slow(members, slowTime / slowRounds)
        }
    }

    private suspend fun read(slot: Slot) {
        probes.acquire()
        if (slot.member.probe(ending(slot, probes))) return
        probes.release()
        permits.acquire()
        slot.member.tick(ending(slot, permits))
    }

    /** What ends a read of [slot] that took one of [limit]'s permits: only the first call counts. */
    private fun ending(slot: Slot, limit: Semaphore): () -> Unit {
        val ended = AtomicBoolean()
        return {
            if (ended.compareAndSet(false, true)) {
                slot.busy.set(false)
                limit.release()
            }
        }
    }

    private companion object {
        /**
         * Probes pending at once. A probe holds no thread here, but each holds one of the answering ORB's request
         * threads while it is served: a JacORB peer made from rtcoord's recipe has 64 (OrbRecipe) for every call the
         * tree makes, and requests beyond them queue and make it warn. Polling 1000 components at 10 Hz sends 50 in a
         * slice, answered within a slice: this limit only slows a round down when the components answer more slowly
         * than that.
         */
        const val PROBES_IN_FLIGHT = 32

        /** Slices per period: reads due within one slice leave together. */
        const val SLICES = 20

        /** The longest slice, whatever the period: a read leaves at most this much before its time. */
        val MAX_SLICE = 10.milliseconds

        /** How much longer than its period a round may take before the schedule says it cannot keep up. */
        const val SLOW = 1.2

        /**
         * Slow rounds in a row that make it say so: a few slow rounds are a hiccup (a collection, the JIT warming up),
         * and the rate said is their mean.
         */
        const val SLOW_ROUNDS = 10
    }
}

/** [this] as a rate: `4.2 Hz`. */
internal fun Duration.asRate(): String = "%.1f Hz".format(1.0 / toDouble(DurationUnit.SECONDS))
