package org.rtcoord.examples

import java.nio.file.Files
import java.nio.file.Paths
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.rtcoord.nameServerPath
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.profile.SystemProfiles
import org.rtcoord.sim.ProfileKeys
import org.rtcoord.sim.SimulatedSystem
import org.rtcoord.sim.SimulationComparison
import org.rtcoord.sim.test.CoordinatorTestRunner

/**
 * A real OpenRTM-aist system saved with `profile save` and simulated: the simulation's fidelity checked against the
 * system it was saved from, and the paper's coordinator test run on the copy, for [OpenRtmPythonTest] and
 * [OpenRtmCppTest].
 */
object OpenRtmSimulationScenarios {
    /**
     * The localisation system, plus a second slave ([extras]) hosting what the pipeline lacks (hidden and constrained
     * configuration sets, service ports with their interfaces, connected), saved and simulated: the comparison of the
     * simulation with the live system finds no difference.
     */
    fun fidelity(installation: OpenRtmInstallation, extras: (OpenRtmSystem) -> Unit): Unit = runBlocking {
        OpenRtmSystem.start(installation).use { system ->
            extras(system)
            val saved = SystemProfiles(system.witness).save(nameServerPath(system.naming))
            SimulatedSystem.start(saved).use { simulation ->
                println(
                    "${installation.label}: simulating the saved system: ${simulation.warnings.joinToString("; ").ifEmpty { "no warnings" }}"
                )
                val comparison = SimulationComparison.of(system.witness, nameServerPath(system.naming), simulation)
                comparison.differences.forEach { println("${installation.label}: difference: $it") }
                println(
                    "${installation.label}: ${comparison.compared} compared, ${comparison.differences.size} differences"
                )
                assertEquals(emptyList<String>(), comparison.differences)
                val slaves =
                    saved.ext.properties
                        .filterKeys { it.startsWith(ProfileKeys.SLAVE_PREFIX) && it.endsWith(".name") }
                        .values
                assertEquals(2, slaves.size, "both slaves saved: $slaves")
                assertTrue(saved.servicePortConnectors.isNotEmpty(), "a service connection saved")
                assertTrue(
                    saved.components.any { it.configurationSet("__constraints__") != null },
                    "a component's constraints saved",
                )
                val interfaces =
                    saved.components
                        .flatMap { it.servicePorts }
                        .flatMap { port ->
                            port.ext.properties.keys.filter { it.startsWith(ProfileKeys.INTERFACE_PREFIX) }
                        }
                assertTrue(interfaces.size >= 2, "service interfaces saved: $interfaces")
                println(
                    "${installation.label}: managers saved: ${saved.ext.properties.filterKeys { it.startsWith("rtcoord.") }}"
                )
            }
        }
    }

    /**
     * The paper's test on the real localisation system's copy: saved from the live system (with the ports of
     * `odo_localise`, which no instance shows, added by hand as `docs/testing.md` says), `localisation.test.kts` run by
     * the test kit on its simulation passes.
     */
    fun paperTestOnCopy(installation: OpenRtmInstallation): Unit = runBlocking {
        val directory = Files.createTempDirectory("rtcoord-copy")
        try {
            val saved =
                OpenRtmSystem.start(installation).use { system ->
                    SystemProfiles(system.witness).save(nameServerPath(system.naming))
                }
            Files.writeString(
                directory.resolve("real.xml"),
                RtsProfiles.write(withOdoLocalisePorts(saved), ProfileFormat.XML),
            )
            Files.copy(Paths.get("localisation.coord.kts"), directory.resolve("localisation.coord.kts"))
            val test = directory.resolve("real.test.kts")
            Files.writeString(
                test,
                Files.readString(Paths.get("localisation.test.kts"))
                    .replace("system(\"localisation.xml\")", "system(\"real.xml\")"),
            )
            val runner = CoordinatorTestRunner(parallelism = 1)
            val results = runner.runAll(runner.files(listOf(test)))
            for (result in results) {
                result.log.forEach {
                    println("${installation.label}: ${result.scenario}: coordinator on the copy: $it")
                }
                println(
                    "${installation.label}: the paper's test on the copy of the real system, ${result.scenario}: ${result.failures.ifEmpty { "passed" }} in ${result.duration}"
                )
            }
            assertEquals(emptyList<String>(), results.flatMap { it.failures }.map { it.toString() })
            assertTrue(results.size >= 2, "every scenario of localisation.test.kts ran: ${results.map { it.scenario }}")
        } finally {
            directory.toFile().deleteRecursively()
        }
    }

    /** [saved] with the ports of `odo_localise`, which the live system can create but shows none of. */
    private fun withOdoLocalisePorts(saved: RtsProfile): RtsProfile =
        saved.withExt(
            saved.ext.withProperties(
                saved.ext.properties +
                    mapOf(
                        ProfileKeys.typePort("odo_localise", "odo") to "DataInPort IDL:RTC/TimedDoubleSeq:1.0",
                        ProfileKeys.typePort("odo_localise", "gyro") to "DataInPort IDL:RTC/TimedDouble:1.0",
                        ProfileKeys.typePort("odo_localise", "pose") to "DataOutPort IDL:RTC/TimedDoubleSeq:1.0",
                    )
            )
        )
}
