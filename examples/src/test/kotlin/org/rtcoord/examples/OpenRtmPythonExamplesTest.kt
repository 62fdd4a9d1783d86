package org.rtcoord.examples

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.rtcoord.EventOptions
import org.rtcoord.FsmStateChanged
import org.rtcoord.LifeCycle
import org.rtcoord.ObserverFlavour
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMethodChanged
import org.rtcoord.profile.ProfileRefusedException
import org.rtcoord.fixtures.awaitValue
import org.rtcoord.profile.SystemProfiles
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.seconds

/**
 * OpenRTM-aist-Python's own example components against rtcoord: ConfigSample, whose sets hold values
 * outside its declared constraints; SequenceOutComponent, whose one-second `on_execute` makes its
 * context answer `RTC_ERROR` to transitions that then happen; and StaticFsm's Microwave, an FSM component. Skipped unless `RTCOORD_OPENRTM_PYTHON`
 * names an installation.
 */
class OpenRtmPythonExamplesTest {
    @Test
    fun `ConfigSample - a saved profile restores onto it unchanged, a value written outside its constraint warns, and strict refuses it`(): Unit = runBlocking {
        OpenRtmPythonSystem.start().use { system ->
            system.startOpenRtmExamples()
            val profiles = SystemProfiles(system.witness)
            val sample = system.witness.component(system.path("ConfigSample0.rtc"))
            val saved = profiles.save().let { all -> all.withComponents(all.components.filter { it.instanceName == "ConfigSample0" }).withDataPortConnectors(emptyList()).withServicePortConnectors(emptyList()) }
            assertEquals("12345", saved.components.single().configurationSet("mode0")!!.data["int_param0"], "configsample.conf's mode0")

            val unchanged = profiles.restore(saved, strict = true)
            assertEquals(emptyList<String>(), unchanged.done + unchanged.warnings)

            sample.setParameter("int_param0", "100", "mode0")
            val outside = "${sample.path}: configuration set 'mode0': int_param0: '12345' is outside 0<=x<=150"
            assertEquals(outside, assertThrows<ProfileRefusedException> { runBlocking { profiles.restore(saved, strict = true) } }.reason)
            assertEquals("100", sample.configuration().sets.getValue("mode0")["int_param0"], "the strict restore wrote nothing")
            val restored = profiles.restore(saved)
            assertEquals(listOf(outside), restored.warnings)
            assertEquals("12345", sample.configuration().sets.getValue("mode0")["int_param0"])
        }
    }

    @Test
    fun `SequenceOutComponent - deactivations behind its one-second on_execute succeed, said to be slow`(): Unit = runBlocking {
        OpenRtmPythonSystem.start().use { system ->
            system.startOpenRtmExamples()
            val sequence = system.witness.component(system.path("SequenceOutComponent0.rtc"))
            val outcomes = (1..4).map {
                sequence.activate()
                sequence.deactivate().also { println("real OpenRTM-aist-Python: SequenceOutComponent0 deactivated: $it") }
            }
            assertTrue(outcomes.all { it.state == LifeCycle.INACTIVE }, outcomes.toString())
            assertEquals(LifeCycle.INACTIVE, sequence.state())
            // The context answers before on_execute returns only when the call came in its last half second.
            assertTrue(outcomes.any { it.slow && it.lateAnswer == "RTC_ERROR" }, outcomes.toString())
        }
    }

    @Test
    fun `StaticFsm Microwave - watched by the OpenRTM observer, its FSM works on, its state said unknown and why`(): Unit = runBlocking {
        OpenRtmPythonSystem.start().use { system ->
            system.startMicrowave()
            val tree = system.witness
            val microwave = tree.component(system.path("Microwave0.rtc"))
            val buttons = tree.component(system.path("fsm_buttons0.rtc"))
            assertTrue(microwave.snapshot().offersFsmService, microwave.snapshot().properties.toString())
            val told = LinkedBlockingQueue<RtcEvent>()
            tree.on(microwave, RtcEvent::class.java, EventOptions()) { told += it }
            val watched = generateSequence { told.poll(10, TimeUnit.SECONDS) }.filterIsInstance<WatchMethodChanged>().first()
            // The FSM4RTC observer, offered too, would break the machine at its first transition (its
            // post-action listeners take one argument and are called with two).
            assertEquals(ObserverFlavour.OPENRTM, (watched.new as WatchMethod.Pushed).flavour)

            // As the example's rtc.conf connects Inputbutton: one connector per event, named for it.
            for (event in listOf("minute", "start", "tick")) {
                buttons.port(event).connect(listOf(microwave.port("event")), mapOf("fsm_event_name" to event), name = event)
            }
            microwave.activate()
            buttons.activate()
            listOf("minute", "start", "tick").forEachIndexed { index, event -> buttons.setParameter("press", "$event $index") }
            awaitValue("the Microwave to cook its minute and be ready again", 10.seconds) {
                system.output("fsm").takeIf { it.contains("Finished") && Regex("Microwave ready").findAll(it).count() == 2 }
            }
            assertEquals(LifeCycle.ACTIVE, microwave.state())
            val fsm = tree.snapshot().component(microwave)?.fsm
            assertEquals(null to "its observer, OpenRTM::ComponentObserver, carries no FSM status", fsm?.state to fsm?.unknownBecause)
            assertTrue(told.none { it is FsmStateChanged || (it is StateChanged && it.new == LifeCycle.ERROR) }, told.toString())
        }
    }
}
