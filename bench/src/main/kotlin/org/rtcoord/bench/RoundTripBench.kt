package org.rtcoord.bench

import RTC.LifeCycleState
import java.nio.file.Path
import java.util.concurrent.locks.LockSupport
import kotlin.time.Duration.Companion.seconds
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.dsl.Coordinator
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.runtime.RtSystem
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * The coordinator's round trip in the paper's scenario: `examples/localisation.coord.kts` watching by push; the laser
 * fails, and the time runs until the new localiser (odo_localise0, created through the manager and connected) is
 * ACTIVE. Each repetition starts a fresh system in this JVM, whose fixtures' states are watched directly (every 0.2 ms)
 * to timestamp the fault, the laser's ERROR and the recovery.
 */
internal class RoundTripBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    /**
     * One recovery, in nanoseconds from the fault; [error] is null when the ERROR state came and went between two
     * looks.
     */
    private class Recovery(val recovered: Long, val error: Long?)

    suspend fun run() {
        report.section(
            "coordinator round trip: localisation, laser fails to odo_localise0 ACTIVE, push (fixtures in the bench JVM)"
        )
        if (!options.scripts) {
            report.skipped(FAULT_TO_RECOVERED, "coordinator scripts are not compiled in a ${options.profile} run")
            return
        }
        val script = installation.root.resolve("examples/localisation.coord.kts")
        val host = ScriptHost(installation.root.resolve("bench/target/script-cache"))
        // The first run compiles the script (or takes it from the cache) and warms the JVM up.
        recover(host, script)
        val runs = List(options.roundTripRepetitions) { recover(host, script) }
        report.row(
            FAULT_TO_RECOVERED,
            Samples.millis(runs.map { it.recovered }),
            "target: under 300 ms (the paper's example polls once per second)",
        )
        val errors = runs.mapNotNull { it.error }
        if (errors.isNotEmpty()) {
            report.row(
                "fault to laser0 ERROR",
                Samples.millis(errors),
                "the fixture's 100 Hz execution context runs the failing step",
            )
            report.row(
                "laser0 ERROR to recovered",
                Samples.millis(runs.filter { it.error != null }.map { it.recovered - it.error!! }),
                "the coordinator's part",
            )
        }
    }

    private suspend fun recover(host: ScriptHost, script: Path): Recovery =
        NamingService.start().use { naming ->
            Scenarios.localisation(naming.corbaloc).use { system ->
                val config = TreeConfig(listOf(naming.address))
                RtcTree(config).use { tree ->
                    Coordinator(tree, host.load(script, emptyList(), config), EventOptions(WatchMode.PUSH)).use {
                        coordinator ->
                        coordinator.start()
                        faultAndRecovery(system)
                    }
                }
            }
        }

    private fun faultAndRecovery(system: RtSystem): Recovery {
        val laser = system.component("laser0")
        val deadline = System.nanoTime() + 30.seconds.inWholeNanoseconds
        val fault = System.nanoTime()
        laser.fail()
        var error: Long? = null
        while (System.nanoTime() < deadline) {
            val now = System.nanoTime()
            if (error == null && laser.state == LifeCycleState.ERROR_STATE) error = now - fault
            val localiser = system.runtime.components.firstOrNull { it.instanceName == "odo_localise0" }
            if (localiser?.state == LifeCycleState.ACTIVE_STATE) return Recovery(now - fault, error)
            LockSupport.parkNanos(200_000)
        }
        error("odo_localise0 was not ACTIVE within 30 s of the laser's fault")
    }

    private companion object {
        const val FAULT_TO_RECOVERED = "fault to recovered"
    }
}
