package org.rtcoord.sim

import org.rtcoord.runtime.RuntimeProcess

/**
 * How a simulated system starts each of its processes: registered with the naming service at [naming], its ORB on
 * [host] keeping [idleRequestThreads] request threads when idle, running [speed] times as fast as the robot's clock
 * ([RuntimeProcess.speed]).
 */
internal class ProcessRecipe(
    val naming: String,
    val host: String,
    val speed: Double,
    val idleRequestThreads: Int,
) {
    /** Starts a process whose components bind their names in [contexts]: by default where OpenRTM-aist's do. */
    fun start(contexts: List<String> = listOf(RuntimeProcess.hostContext)): RuntimeProcess =
        RuntimeProcess.start(naming, contexts, host = host, speed = speed, idleRequestThreads = idleRequestThreads)
}
