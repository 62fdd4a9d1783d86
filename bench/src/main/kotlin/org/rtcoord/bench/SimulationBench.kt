package org.rtcoord.bench

import java.nio.file.Files
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.sim.SimulatedSystem

/**
 * Starting a simulated system: [MixedSystem]'s N components of mixed types (with their connections and the master and
 * two slaves they were saved with), from its saved profile. **Library**: in the warm bench JVM, `SimulatedSystem.start`
 * until every component is bound, connected and active (its close untimed). **Whole process**: `./rtcoord sim FILE`
 * with an empty stdin, from its start to its exit: the JVM, the simulation's start, the `ready` line, and its shutdown.
 * No peer simulates OpenRTM-aist systems; the target is the issue's, 3 s.
 */
internal class SimulationBench(
    private val options: BenchOptions,
    private val installation: Installation,
    private val report: Report,
) {
    fun run() {
        val n = options.simulationSize
        val profile = MixedSystem.saved(n)
        val connections = profile.dataPortConnectors.size + profile.servicePortConnectors.size
        val file = Files.createTempFile("bench-simulation", ".xml")
        try {
            Files.writeString(file, RtsProfiles.write(profile, ProfileFormat.XML))
            report.section(
                "simulation start, N=${profile.components.size} mixed components, $connections connections, a master and two slaves"
            )
            library(profile)
            process(file.toString(), profile.components.size)
        } finally {
            Files.deleteIfExists(file)
        }
    }

    private fun library(profile: org.rtcoord.profile.RtsProfile) {
        fun once(): Long {
            val start = System.nanoTime()
            val system = SimulatedSystem.start(profile)
            val nanos = System.nanoTime() - start
            system.use {
                check(it.components.size == profile.components.size) {
                    "simulated ${it.components.size} of ${profile.components.size} components: ${it.warnings}"
                }
            }
            return nanos
        }
        repeat(options.libraryWarmups) { once() }
        report.row(
            "rtcoord SimulatedSystem.start in a warm JVM",
            Samples.seconds(List(options.simulationRepetitions) { once() }),
            "target under 3 s",
        )
    }

    private fun process(file: String, size: Int) {
        installation.cliMissing?.let {
            return report.skipped(RTCOORD_SIM, it)
        }
        val command =
            TimedCommand(RTCOORD_SIM, listOf(installation.launcher.toString(), "sim", file), installation.root)
        val (times) =
            timeInterleaved(listOf(command), options.processWarmups, options.simulationRepetitions) { _, run ->
                check("ready $size components" in run.output) { "rtcoord sim printed ${run.output}" }
            }
        report.row(RTCOORD_SIM, times, "JVM start, the simulation's start and its shutdown; target under 3 s")
    }

    private companion object {
        const val RTCOORD_SIM = "rtcoord sim FILE, whole process (stdin empty)"
    }
}
