package org.rtcoord.examples

import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.EnumSource
import org.rtcoord.FsmStateChanged
import org.rtcoord.LifeCycle
import org.rtcoord.ManagerNode
import org.rtcoord.ObserverFlavour
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged
import org.rtcoord.fixtures.runPeer

/**
 * The paper's coordinator against real OpenRTM-aist C++ 2.0 managers (`rtcd2`) and our components in
 * `examples/openrtm-cpp` ([OpenRtmScenarios]), on each of the three observer builds ([OpenRtmCppBuild]), and an FSM
 * component on the default one: skipped unless `RTCOORD_OPENRTM_CPP` names what `scripts/openrtm-cpp.sh` built.
 */
class OpenRtmCppTest {
    @ParameterizedTest
    @EnumSource(OpenRtmCppBuild::class)
    fun `data - a tap decodes a real out-port's scans, and its connector leaves with it`(build: OpenRtmCppBuild): Unit =
        OpenRtmScenarios.data(OpenRtmCpp.named(build))

    @ParameterizedTest
    @EnumSource(OpenRtmCppBuild::class)
    fun `localisation - a laser that stays broken is replaced by the odometry-gyro localiser a real master creates`(
        build: OpenRtmCppBuild
    ): Unit = OpenRtmScenarios.localisation(OpenRtmCpp.named(build))

    @ParameterizedTest
    @EnumSource(OpenRtmCppBuild::class)
    fun `supervision - the slave manager hosting the pipeline is killed, and a real master re-creates it in a slave it starts`(
        build: OpenRtmCppBuild
    ): Unit = OpenRtmScenarios.supervision(OpenRtmCpp.named(build))

    @ParameterizedTest
    @EnumSource(OpenRtmCppBuild::class)
    fun `modes - with a laser that stays broken the system runs on odometry, and on the laser again once it is repaired`(
        build: OpenRtmCppBuild
    ): Unit = OpenRtmScenarios.modes(OpenRtmCpp.named(build))

    @ParameterizedTest
    @EnumSource(OpenRtmCppBuild::class)
    fun `watching - each build's observer pushes the changes, the legacy one when both are offered, and no observer means polling`(
        build: OpenRtmCppBuild
    ): Unit = runBlocking {
        OpenRtmSystem.start(OpenRtmCpp.named(build)).use { system ->
            val gyro = system.witness.component(system.path("gyro0.rtc"))
            val events = Channel<RtcEvent>(Channel.UNLIMITED)
            system.witness.on(gyro, setOf(WatchMethodChanged::class.java, StateChanged::class.java)) {
                events.trySend(it)
            }
            suspend fun <E : RtcEvent> next(type: Class<E>): E =
                withTimeout(10.seconds) {
                    var event = events.receive()
                    while (!type.isInstance(event)) event = events.receive()
                    type.cast(event)
                }
            val method = next(WatchMethodChanged::class.java).new
            when (build) {
                OpenRtmCppBuild.DEFAULT ->
                    assertEquals(ObserverFlavour.OMG, (method as WatchMethod.Pushed).flavour, "$method")
                OpenRtmCppBuild.NO_OBSERVER -> assertTrue(method is WatchMethod.Polled, "$method")
                // Attaching the FSM4RTC flavour here would crash rtcd2: the library and the module each define a
                // ComponentObserverConsumer.
                OpenRtmCppBuild.BOTH_OBSERVERS ->
                    assertEquals(ObserverFlavour.OPENRTM, (method as WatchMethod.Pushed).flavour, "$method")
            }
            for ((action, state) in
                listOf(
                    suspend { gyro.deactivate() } to LifeCycle.INACTIVE,
                    suspend { gyro.activate() } to LifeCycle.ACTIVE,
                )) {
                val asked = TimeSource.Monotonic.markNow()
                action()
                val told = next(StateChanged::class.java)
                println(
                    "${system.installation.label}: gyro0 ${told.new} told ${asked.elapsedNow()} after asking ($method)"
                )
                assertEquals(state, told.new)
            }
            assertEquals(LifeCycle.ACTIVE, gyro.state(), "the slave manager lives on with the observer attached")
        }
    }

    @Test
    fun `slaves - a C++ slave carries its master's name, rtls names it so, and rtcoord by its own instance name`():
        Unit = runBlocking {
        OpenRtmSystem.start(OpenRtmCpp.named(OpenRtmCppBuild.DEFAULT)).use { system ->
            val master = system.witness.manager(system.path("manager.mgr"))
            val slave = master.children().filterIsInstance<ManagerNode>().single()
            assertEquals("pipeline", slave.name)
            assertEquals(
                mapOf("name" to "manager", "instance_name" to "pipeline"),
                slave.profile().filterKeys { it == "name" || it == "instance_name" },
            )
            // rtls shows every C++ slave of this master as `manager`: the supervision scenario shows why rtcoord does
            // not.
            val listed =
                runPeer("rtls", system.path("manager.mgr")).ok().output.split(Regex("\\s+")).map {
                    it.removeSuffix("/")
                }
            println("${system.installation.label}: rtls ${system.path("manager.mgr")}: $listed")
            assertTrue("manager" in listed && "pipeline" !in listed, "$listed")
        }
    }

    @ParameterizedTest
    @EnumSource(OpenRtmCppBuild::class)
    fun `configuration - a saved profile restores onto a component whose set holds a value outside its constraint`(
        build: OpenRtmCppBuild
    ): Unit =
        OpenRtmSystem.start(OpenRtmCpp.named(build)).use { system ->
            startOwnComponents(system)
            OpenRtmConfigurationScenarios.roundTrip(system, "config_sample0")
        }

    @ParameterizedTest
    @EnumSource(OpenRtmCppBuild::class)
    fun `transitions - deactivations behind an on_deactivated longer than the transition timeout succeed, said to be slow`(
        build: OpenRtmCppBuild
    ): Unit =
        OpenRtmSystem.start(OpenRtmCpp.named(build)).use { system ->
            startOwnComponents(system)
            val outcomes = OpenRtmConfigurationScenarios.deactivations(system, "slow_stop0")
            // rtcd2's context waits transition_timeout (0.5 s) for INACTIVE, then answers RTC_ERROR: every time.
            assertTrue(
                outcomes.all { it.slow && it.lateAnswer == "RTC_ERROR" && it.elapsedMillis >= 500 },
                outcomes.toString(),
            )
        }

    @Test
    fun `fidelity - the real system saved and simulated, with a second slave, service ports and constraints, shows no difference`():
        Unit = OpenRtmSimulationScenarios.fidelity(OpenRtmCpp.named(OpenRtmCppBuild.DEFAULT), ::startExtras)

    @Test
    fun `paper's test on the copy - localisation test kts passes on the simulation of the saved real system`(): Unit =
        OpenRtmSimulationScenarios.paperTestOnCopy(OpenRtmCpp.named(OpenRtmCppBuild.DEFAULT))

    @Test
    fun `StaticFsm Microwave - the FSM4RTC observer tells each state the machine enters`(): Unit = runBlocking {
        OpenRtmSystem.start(OpenRtmCpp.named(OpenRtmCppBuild.DEFAULT)).use { system ->
            startMicrowave(system)
            val tree = system.witness
            val microwave = tree.component(system.path("fsm_microwave0.rtc"))
            assertTrue(microwave.snapshot().offersFsmService, microwave.snapshot().properties.toString())
            val told = Channel<RtcEvent>(Channel.UNLIMITED)
            tree.on(microwave, setOf(WatchMethodChanged::class.java, FsmStateChanged::class.java)) { told.trySend(it) }
            suspend fun <E : RtcEvent> next(type: Class<E>): E =
                withTimeout(10.seconds) {
                    var event = told.receive()
                    while (!type.isInstance(event)) event = told.receive()
                    type.cast(event)
                }
            assertEquals(ObserverFlavour.OMG, (next(WatchMethodChanged::class.java).new as WatchMethod.Pushed).flavour)

            microwave.activate()
            val entered =
                listOf("minute", "start", "tick").mapIndexed { index, event ->
                    microwave.setParameter("press", "$event $index")
                    next(FsmStateChanged::class.java).new
                }
            println("${system.installation.label}: fsm_microwave0 entered $entered")
            assertEquals(listOf("Programmed", "Cooking", "Idle"), entered)
            assertTrue(system.output("fsm").contains(">>> Finished <<<"), system.output("fsm"))
            val fsm = tree.snapshot().component(microwave)?.fsm
            assertEquals("Idle" to null, fsm?.state to fsm?.unknownBecause)
            assertEquals(LifeCycle.ACTIVE, microwave.state())
        }
    }

    /**
     * Starts `fsm_microwave0` (OpenRTM-aist's StaticFsm Microwave machine, see `fsm_microwave.cpp`), inactive, in a
     * manager of their own that loads the FSM4RTC observer and the `ExtendedFsmService` provider.
     */
    private fun startMicrowave(system: OpenRtmSystem) {
        val installation = system.installation
        system.startOwnManager(
            "fsm",
            installation.loadPath,
            listOf("fsm_microwave0"),
            "manager.preload.modules: ComponentObserverConsumer.so, ExtendedFsmServiceProvider.so",
            "manager.modules.preload: ${installation.module("fsm_microwave")}",
            "manager.components.precreate: fsm_microwave",
        )
    }

    /**
     * Starts a second slave of the master, `extras`, hosting `config_sample0` (a set outside its constraints) and
     * `probe_server0` and `probe_client0`, whose service ports (interface `probe` of type `SDOPackage::SDOService`) are
     * connected. All inactive.
     */
    private fun startExtras(system: OpenRtmSystem) {
        val installation = system.installation
        system.startSlave(
            "extras",
            system.directory,
            installation.loadPath,
            listOf("config_sample0", "probe_server0", "probe_client0"),
            "manager.modules.preload: ${listOf("config_sample", "probe_server", "probe_client").joinToString(", ") { installation.module(it) }}",
            "manager.components.precreate: config_sample, probe_server, probe_client",
        )
        runBlocking {
            system.witness.connect(system.path("probe_server0.rtc:probe"), system.path("probe_client0.rtc:probe"))
        }
    }

    /** Starts `config_sample0` and `slow_stop0`, inactive, in a manager of their own. */
    private fun startOwnComponents(system: OpenRtmSystem) {
        val installation = system.installation
        system.startOwnManager(
            "own",
            installation.loadPath,
            listOf("config_sample0", "slow_stop0"),
            "manager.modules.preload: ${installation.module("config_sample")}, ${installation.module("slow_stop")}",
            "manager.components.precreate: config_sample, slow_stop",
        )
    }
}
