@file:OptIn(InternalRtcoordApi::class)

package org.rtcoord.sim.test

import kotlin.time.ComparableTimeMark
import kotlin.time.Duration
import kotlinx.coroutines.CoroutineScope
import org.rtcoord.InternalRtcoordApi
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.internal.treeTime

/**
 * A scenario's clock: the robot's time, which the simulated system, its tree and the coordinator run [speed] times as
 * fast as the host's ([TreeConfig.speed]). The steps' and faults' times, the expectations' deadlines and the run's
 * waits follow it; the run's own guards (a coordinator that does not start, an observer that does not drain) and its
 * reported duration stay on the host's clock.
 */
internal class ScenarioClock(tree: RtcTree) {
    private val speed: Double = tree.config.speed
    private val time = tree.treeTime()

    fun markNow(): ComparableTimeMark = time.markNow()

    /** Waits [duration] of the robot's time. */
    suspend fun delay(duration: Duration) = kotlinx.coroutines.delay(onHost(duration))

    /** Runs [block] for at most [duration] of the robot's time; null if it had not finished by then. */
    suspend fun <T> withTimeoutOrNull(duration: Duration, block: suspend CoroutineScope.() -> T): T? =
        kotlinx.coroutines.withTimeoutOrNull(onHost(duration), block)

    /** The robot's time that [host] of the host's clock stands for. */
    fun robotTime(host: Duration): Duration = host * speed

    private fun onHost(duration: Duration): Duration = duration / speed
}
