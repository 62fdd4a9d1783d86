package org.rtcoord.internal.events

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.delay
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Semaphore
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicBoolean
import kotlin.coroutines.CoroutineContext
import kotlin.coroutines.EmptyCoroutineContext
import kotlin.time.Duration
import kotlin.time.DurationUnit
import kotlin.time.TimeSource

/**
 * Every component of a tree polled at one [period], on one schedule: each round reads every member once,
 * their reads spread evenly over the period (member i of n at i/n of it) rather than all at once, with at
 * most [inFlight] reads pending. When the reads cannot keep up, a round simply takes longer: every member
 * is then read at the same, lower rate, and [slow] is told once (after [SLOW_ROUNDS] slow rounds in a row)
 * what that rate is. Ticks a round could not serve in time count as [missed] (a member whose previous
 * read still waits, a hung component, is passed over in that round rather than holding the others up).
 * Its rounds run in [context]: on the dispatcher the members read on, a tick and its read pass from one
 * to the other without waking a thread.
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
    /** One polled component: [tick] asks it to read, and it calls `done` once the read has ended (or failed). */
    fun interface Member {
        fun tick(done: () -> Unit)
    }

    private class Slot(val member: Member) {
        val busy = AtomicBoolean()
    }

    private val slots = CopyOnWriteArrayList<Slot>()
    private val joined = Channel<Unit>(Channel.CONFLATED)
    private val permits = Semaphore(inFlight)
    private var warned = false
    private var overdue = 0.0

    /** Rounds in a row that overran with as many members, and how long they took together. */
    private var slowRounds = 0
    private var slowTime = Duration.ZERO
    private var lastMembers = 0

    private val rounds: Job = scope.launch(context) {
        while (isActive) {
            val members = slots.toList()
            if (members.isEmpty()) {
                joined.receive()
                continue
            }
            round(members)
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

    private suspend fun round(members: List<Slot>) {
        val start = time.markNow()
        var passedOver = 0L
        members.forEachIndexed { index, slot ->
            delay(period * index.toDouble() / members.size - start.elapsedNow())
            // Its previous read still waits (a hung component): this round goes on without it.
            if (!slot.busy.compareAndSet(false, true)) {
                passedOver++
                return@forEachIndexed
            }
            permits.acquire()
            val released = AtomicBoolean()
            slot.member.tick {
                if (released.compareAndSet(false, true)) {
                    slot.busy.set(false)
                    permits.release()
                }
            }
        }
        delay(period - start.elapsedNow())
        val took = start.elapsedNow()
        // A round that took 1.5 periods left half a tick of every member unserved.
        overdue += members.size * ((took - period) / period).coerceAtLeast(0.0)
        val late = overdue.toLong()
        overdue -= late
        if (late + passedOver > 0) missed(late + passedOver)
        // Only a schedule that stays slow with the same members says so: not one still being filled.
        if (took <= period * SLOW || members.size != lastMembers) {
            lastMembers = members.size
            slowRounds = 0
            slowTime = Duration.ZERO
            return
        }
        slowRounds++
        slowTime += took
        if (!warned && slowRounds == SLOW_ROUNDS) {
            warned = true
            slow(members.size, slowTime / slowRounds)
        }
    }

    private companion object {
        /** How much longer than its period a round may take before the schedule says it cannot keep up. */
        const val SLOW = 1.2

        /** Slow rounds in a row that make it say so: a few slow rounds are a hiccup (a collection, the JIT warming up), and the rate said is their mean. */
        const val SLOW_ROUNDS = 10
    }
}

/** [this] as a rate: `4.2 Hz`. */
internal fun Duration.asRate(): String = "%.1f Hz".format(1.0 / toDouble(DurationUnit.SECONDS))
