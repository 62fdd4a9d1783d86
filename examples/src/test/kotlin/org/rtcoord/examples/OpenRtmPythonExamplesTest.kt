package org.rtcoord.examples

import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.FsmStateChanged
import org.rtcoord.LifeCycle
import org.rtcoord.ObserverFlavour
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged
import org.rtcoord.fixtures.awaitValue

/**
 * OpenRTM-aist-Python's own example components against rtcoord: ConfigSample, whose sets hold values outside its
 * declared constraints, and SequenceOutComponent, whose one-second `on_execute` makes its context answer `RTC_ERROR` to
 * transitions that then happen; and StaticFsm's Microwave, an FSM component. Skipped unless `RTCOORD_OPENRTM_PYTHON`
 * names an installation.
 */
class OpenRtmPythonExamplesTest {
    @Test
    fun `ConfigSample - a saved profile restores onto it unchanged, a value written outside its constraint warns, and strict refuses it`():
        Unit =
        OpenRtmSystem.start(OpenRtmPython.named()).use { system ->
            startOpenRtmExamples(system)
            OpenRtmConfigurationScenarios.roundTrip(system, "ConfigSample0")
        }

    @Test
    fun `SequenceOutComponent - deactivations behind its one-second on_execute succeed, said to be slow`(): Unit =
        OpenRtmSystem.start(OpenRtmPython.named()).use { system ->
            startOpenRtmExamples(system)
            val outcomes = OpenRtmConfigurationScenarios.deactivations(system, "SequenceOutComponent0")
            // The context answers before on_execute returns only when the call came in its last half second.
            assertTrue(outcomes.any { it.slow && it.lateAnswer == "RTC_ERROR" }, outcomes.toString())
        }

    @Test
    fun `StaticFsm Microwave - watched by the OpenRTM observer, its FSM works on, its state said unknown and why`():
        Unit = runBlocking {
        OpenRtmSystem.start(OpenRtmPython.named()).use { system ->
            startMicrowave(system)
            val tree = system.witness
            val microwave = tree.component(system.path("Microwave0.rtc"))
            val buttons = tree.component(system.path("fsm_buttons0.rtc"))
            assertTrue(microwave.snapshot().offersFsmService, microwave.snapshot().properties.toString())
            val told = LinkedBlockingQueue<RtcEvent>()
            tree.on(microwave, RtcEvent::class.java, EventOptions()) { told += it }
            val watched = generateSequence {
                told.poll(10, TimeUnit.SECONDS)
            }
                .filterIsInstance<WatchMethodChanged>()
                .first()
            // The FSM4RTC observer, offered too, would break the machine at its first transition (its
            // post-action listeners take one argument and are called with two).
            assertEquals(ObserverFlavour.OPENRTM, (watched.new as WatchMethod.Pushed).flavour)

            // As the example's rtc.conf connects Inputbutton: one connector per event, named for it.
            for (event in listOf("minute", "start", "tick")) {
                buttons
                    .port(event)
                    .connect(listOf(microwave.port("event")), mapOf("fsm_event_name" to event), name = event)
            }
            microwave.activate()
            buttons.activate()
            listOf("minute", "start", "tick").forEachIndexed { index, event ->
                buttons.setParameter("press", "$event $index")
            }
            awaitValue("the Microwave to cook its minute and be ready again", 10.seconds) {
                system.output("fsm").takeIf {
                    it.contains("Finished") && Regex("Microwave ready").findAll(it).count() == 2
                }
            }
            assertEquals(LifeCycle.ACTIVE, microwave.state())
            val fsm = tree.snapshot().component(microwave)?.fsm
            assertEquals(
                null to "its observer, OpenRTM::ComponentObserver, carries no FSM status",
                fsm?.state to fsm?.unknownBecause,
            )
            assertTrue(
                told.none { it is FsmStateChanged || (it is StateChanged && it.new == LifeCycle.ERROR) },
                told.toString(),
            )
        }
    }

    /**
     * Starts OpenRTM-aist's own ConfigSample (with its `configsample.conf`: sets `mode0` and `mode1` hold values
     * outside its `__constraints__`) and SeqIO's `SequenceOutComponent` (its `on_execute` sleeps 1 s) from the
     * installation's examples, inactive, in a manager of their own.
     */
    private fun startOpenRtmExamples(system: OpenRtmSystem) {
        val examples = (system.installation as OpenRtmPython).examples()
        system.startOwnManager(
            "examples",
            listOf(examples.resolve("ConfigSample"), examples.resolve("SeqIO")),
            listOf("ConfigSample0", "SequenceOutComponent0"),
            "manager.modules.preload: ConfigSample.py, SeqOut.py",
            "manager.components.precreate: ConfigSample, SeqOut",
            "example.ConfigSample.config_file: ${examples.resolve("ConfigSample/configsample.conf")}",
        )
    }

    /**
     * Starts OpenRTM-aist's StaticFsm `Microwave` from the installation's examples and `fsm_buttons` (from
     * `examples/openrtm-python`, the example's Inputbutton pressed through configuration), inactive and unconnected, in
     * a manager of their own that loads the FSM4RTC observer (`ext/fsm4rtc_observer`) beside the OpenRTM one every
     * Python manager has, and the `ExtendedFsmService` provider (`ext/extended_fsm`).
     */
    private fun startMicrowave(system: OpenRtmSystem) {
        val installation = system.installation as OpenRtmPython
        val ext = installation.examples().resolveSibling("ext")
        system.startOwnManager(
            "fsm",
            listOf(
                ext.resolve("fsm4rtc_observer"),
                ext.resolve("extended_fsm"),
                installation.examples().resolve("StaticFsm"),
                installation.components,
            ),
            listOf("Microwave0", "fsm_buttons0"),
            "manager.modules.preload: ComponentObserverConsumer.py, ExtendedFsmServiceProvider.py, Microwave.py, fsm_buttons.py",
            "manager.components.precreate: Microwave, fsm_buttons",
        )
    }
}
