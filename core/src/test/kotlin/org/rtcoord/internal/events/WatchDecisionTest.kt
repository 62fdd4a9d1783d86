package org.rtcoord.internal.events

import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.ObserverFlavour
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMode

/** How a component is watched, from what its registrations ask for and how attaching an observer went. */
class WatchDecisionTest {
    private val auto = EventOptions(WatchMode.AUTO, pollPeriod = 500.milliseconds, heartbeat = 2.seconds)
    private val push = EventOptions(WatchMode.PUSH, heartbeat = 1.seconds)
    private val poll = EventOptions(WatchMode.POLL, pollPeriod = 100.milliseconds)
    private val attached = Attachment.Attached(ObserverFlavour.OMG)
    private val notOffered = Attachment.NotOffered(emptyList())

    @Test
    fun `an attached observer pushes, at the shortest heartbeat asked for, polled too only where asked`() {
        assertEquals(
            WatchMethod.Pushed(ObserverFlavour.OMG, 1.seconds, null),
            decideWatchMethod(listOf(auto, push), attached),
        )
        assertEquals(
            WatchMethod.Pushed(ObserverFlavour.OMG, 2.seconds, 100.milliseconds),
            decideWatchMethod(listOf(auto, poll), attached),
        )
    }

    @Test
    fun `polling asked for says so, whatever the component offers`() {
        assertEquals(
            WatchMethod.Polled(100.milliseconds, "polling was asked for"),
            decideWatchMethod(listOf(poll), Attachment.NotTried),
        )
        // An observer left attached for a registration that has gone does not count.
        assertEquals(
            WatchMethod.Polled(100.milliseconds, "polling was asked for"),
            decideWatchMethod(listOf(poll), attached),
        )
    }

    @Test
    fun `without an observer, automatic registrations are polled and say why`() {
        assertEquals(
            WatchMethod.Polled(
                500.milliseconds,
                "it offers no ComponentObserver (sdo.service.consumer.available_services: none)",
            ),
            decideWatchMethod(listOf(auto), notOffered),
        )
        assertEquals(
            WatchMethod.Polled(
                100.milliseconds,
                "it refused the OpenRTM::ComponentObserver and the RTC::ComponentObserver (FSM4RTC)",
            ),
            decideWatchMethod(listOf(auto, poll), Attachment.Refused(ObserverFlavour.values().toList())),
        )
        assertEquals(
            WatchMethod.Polled(
                500.milliseconds,
                "attaching an observer failed: get_configuration: unreachable (TRANSIENT)",
            ),
            decideWatchMethod(listOf(auto), Attachment.Failed("get_configuration: unreachable (TRANSIENT)")),
        )
    }

    @Test
    fun `push alone without an observer watches nothing, and says why`() {
        assertEquals(
            WatchMethod.Unwatched(
                "it offers no ComponentObserver (sdo.service.consumer.available_services: IDL:other/Service:1.0)"
            ),
            decideWatchMethod(listOf(push), Attachment.NotOffered(listOf("IDL:other/Service:1.0"))),
        )
    }

    @Test
    fun `nothing is decided for nobody`() {
        assertNull(decideWatchMethod(emptyList(), attached))
    }
}
