package org.rtcoord

import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.runtime.ObserverFlavour as FixtureFlavour
import org.rtcoord.runtime.Scenarios

/**
 * Which ComponentObserver the tree attaches when a component offers both: the legacy `OpenRTM::ComponentObserver`.
 * OpenRTM-aist C++ 2.0.2 built with `OBSERVER_ENABLE=ON` and the FSM4RTC module preloaded offers both, and attaching
 * the FSM4RTC one there crashes `rtcd2` (the library and the module each define a class of the same name);
 * `OpenRtmCppTest` runs that build.
 */
class ObserverChoiceTest {
    private val localisation = LocalisationSystem()

    @AfterEach fun stop() = localisation.close()

    @Test
    fun `a component offering both flavours, the FSM4RTC one first, is pushed by the legacy one`(): Unit = runBlocking {
        localisation.system.runtime.create(
            Scenarios.relay.acceptingObservers(FixtureFlavour.OMG, FixtureFlavour.OPENRTM),
            "both0",
        )
        val both = localisation.tree.component(localisation.path("both0.rtc"))
        val told = EventRecorder()
        localisation.tree.on(
            both,
            RtcEvent::class.java,
            EventOptions(pollPeriod = 200.milliseconds, heartbeat = 500.milliseconds),
            told.handler,
        )

        assertEquals(
            WatchMethodChanged(both, null, WatchMethod.Pushed(ObserverFlavour.OPENRTM, 500.milliseconds, null)),
            told.next<WatchMethodChanged>(),
        )
        assertEquals(1, localisation.system.component("both0").observerIds.size)
    }
}
