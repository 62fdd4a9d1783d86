package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.milliseconds
import org.rtcoord.internal.TreeCore
import org.slf4j.LoggerFactory

/** The tree's poll schedules, one per period: made with its first member, stopped with its last. */
internal class PollSchedules(private val core: TreeCore) {
    private val log = LoggerFactory.getLogger("org.rtcoord.RtcTree")
    private val schedules = HashMap<Duration, PollSchedule>()

    /** Reads [member] every [period], on the schedule of every component polled at that period. */
    fun add(period: Duration, member: PollSchedule.Member) {
        synchronized(schedules) {
            schedules
                .getOrPut(period) {
                    val slow = { members: Int, achieved: Duration ->
                        log.warn(
                            "polling {} components every {} cannot keep up: each is read every {} ({}) instead",
                            members,
                            period,
                            achieved.inWholeMilliseconds.milliseconds,
                            achieved.asRate(),
                        )
                    }
                    PollSchedule(
                        core.scope,
                        period,
                        POLLS_IN_FLIGHT,
                        { core.missedPollTicks.addAndGet(it) },
                        slow,
                        core.time,
                        core.remote.dispatcher,
                    )
                }
                .add(member)
        }
    }

    /** Stops reading [member] every [period]. */
    fun remove(period: Duration, member: PollSchedule.Member) {
        synchronized(schedules) {
            val schedule = schedules[period] ?: return
            if (schedule.remove(member)) {
                schedules.remove(period)
                schedule.stop()
            }
        }
    }

    /** Stops every schedule. */
    fun close() {
        synchronized(schedules) {
            schedules.values.forEach(PollSchedule::stop)
            schedules.clear()
        }
    }

    private companion object {
        /**
         * Poll reads pending at once, whatever the number of components. Measured polling 1000 fixtures at 10 Hz
         * (bench/README.md, "where the time goes"): 2 to 4 in flight read as many components a second as 32 for less
         * CPU per read (96 against 118 us); 16 made JacORB's request pool thrash.
         */
        const val POLLS_IN_FLIGHT = 4
    }
}
