package org.rtcoord

import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.runtime.ObserverFlavour as FixtureFlavour
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.Scenarios

/**
 * An FSM component (the fixtures' model of OpenRTM-aist's StaticFsm Microwave) watched over IIOP: its machine's state
 * is learnt from its FSM4RTC observer's FSM_STATUS hints alone, and where that cannot be, the tree says why.
 */
class FsmWatchTest {
    private val localisation = LocalisationSystem()
    private val tree = localisation.tree

    @AfterEach fun stop() = localisation.close()

    private suspend fun microwave(
        name: String,
        vararg flavours: FixtureFlavour,
    ): Pair<RuntimeComponent, ComponentNode> {
        val type = if (flavours.isEmpty()) Scenarios.microwave else Scenarios.microwave.acceptingObservers(*flavours)
        val fixture = localisation.system.runtime.create(type, name)
        return fixture to tree.component(localisation.path("$name.rtc"))
    }

    private fun fsmOf(node: ComponentNode): FsmStatus? = tree.snapshot().component(node)?.fsm

    @Test
    fun `each state entered is an event, and the model holds the last one`(): Unit = runBlocking {
        val (fixture, node) = microwave("Microwave0")
        val told = EventRecorder()
        tree.on(node, RtcEvent::class.java, EventOptions(), told.handler)
        assertEquals(
            ObserverFlavour.OMG,
            (told.next<WatchMethodChanged>().new as WatchMethod.Pushed).flavour,
            "the flavour it offers, as C++ 2.0 by default",
        )
        assertEquals(
            FsmStatusImpl(null, "not told yet: OpenRTM-aist tells the state only when it changes"),
            fsmOf(node),
        )

        fixture.fsmEvent("minute")
        assertEquals(FsmStateChanged(node, null, "Programmed"), told.next<FsmStateChanged>())
        fixture.fsmEvent("open")
        assertEquals(FsmStateChanged(node, "Programmed", "Disabled"), told.next<FsmStateChanged>())
        fixture.fsmEvent("close")
        assertEquals(
            FsmStateChanged(node, "Disabled", "Operational"),
            told.next<FsmStateChanged>(),
            "entering a nested state enters each on the way down",
        )
        assertEquals(FsmStateChanged(node, "Operational", "Idle"), told.next<FsmStateChanged>())
        assertEquals(FsmStatusImpl("Idle", null), fsmOf(node))
        assertTrue(told.drained<FsmStateChanged>().isEmpty(), "leaving a state or initialising one is no event")
    }

    @Test
    fun `where no FSM4RTC observer listens, the state is unknown and the tree says why`(): Unit = runBlocking {
        val (legacy, legacyNode) = microwave("Microwave1", FixtureFlavour.OPENRTM)
        val (_, unwatchedNode) = microwave("Microwave2", FixtureFlavour.OPENRTM, FixtureFlavour.OMG)
        val (_, polledNode) = microwave("Microwave3")
        val legacyTold = EventRecorder()
        val polledTold = EventRecorder()
        tree.on(legacyNode, RtcEvent::class.java, EventOptions(), legacyTold.handler)
        tree.on(
            polledNode,
            RtcEvent::class.java,
            EventOptions(WatchMode.POLL, pollPeriod = 100.milliseconds),
            polledTold.handler,
        )
        legacyTold.next<WatchMethodChanged>()
        polledTold.next<WatchMethodChanged>()
        unwatchedNode.snapshot()

        legacy.fsmEvent("minute")
        assertEquals(
            FsmStatusImpl(null, "its observer, OpenRTM::ComponentObserver, carries no FSM status"),
            fsmOf(legacyNode),
        )
        assertEquals(
            FsmStatusImpl(null, "polled: OpenRTM-aist tells the state only to FSM4RTC observers"),
            fsmOf(polledNode),
        )
        assertEquals(
            FsmStatusImpl(null, "not watched: OpenRTM-aist tells the state only to FSM4RTC observers, as it changes"),
            fsmOf(unwatchedNode),
        )
        assertNull(
            fsmOf(tree.component(localisation.path("laser0.rtc"))),
            "a component without an FSM has no FSM status",
        )
    }
}
