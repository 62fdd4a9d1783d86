package org.rtcoord.internal.events

import kotlin.time.Duration
import kotlin.time.Duration.Companion.hours
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.ObserverFlavour
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMode
import org.rtcoord.internal.events.ComponentLiveness.Change
import org.rtcoord.internal.events.ComponentLiveness.State.ANSWERING
import org.rtcoord.internal.events.ComponentLiveness.State.FINALIZED
import org.rtcoord.internal.events.ComponentLiveness.State.UNREACHABLE

/**
 * How a component is watched, step by step as its monitor carries the steps out: attaching, detaching and attaching its
 * observer anew, probing it while it does not answer, and the method that says so. Each step is what the machine
 * returns; the test plays the monitor, and nothing here waits.
 */
class WatchArrangementTest {
    private val push = EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds)
    private val auto = EventOptions(WatchMode.AUTO, pollPeriod = 500.milliseconds, heartbeat = 1.seconds)
    private val attached = Attachment.Attached(ObserverFlavour.OPENRTM)
    private val services = "IDL:OpenRTM/ComponentObserver:1.0"

    private fun asking(vararg options: EventOptions, traffic: Duration = 1.hours) =
        WatchNeeds(options.toList(), statesOnly = true, traffic = traffic)

    /** An arrangement whose registrations ask for [options], carried through to its observer attached. */
    private fun observing(vararg options: EventOptions): WatchArrangement =
        WatchArrangement().apply {
            needs = asking(*options)
            reconfigured()
            answered(recovered = false, ANSWERING, services)
            attached(attached, ANSWERING)
            answered(recovered = false, ANSWERING, services)
        }

    @Test
    fun `a push registration attaches an observer after a whole read, reads again, and then says it is pushed`() {
        val arrangement = WatchArrangement()
        arrangement.needs = asking(push)
        assertEquals(WatchStep.ReadAll, arrangement.reconfigured())
        val attach = arrangement.answered(recovered = false, ANSWERING, services).next as WatchStep.Attach
        assertEquals(services, attach.advertised)
        assertEquals(200.milliseconds, attach.heartbeat)
        assertEquals(1.hours, attach.traffic, "no registration asked for traffic")
        assertFalse(arrangement.observed)
        assertEquals(
            WatchStep.ReadAll,
            arrangement.attached(attached, ANSWERING).next,
            "a change before the attachment sent its hint to nobody",
        )
        assertTrue(arrangement.observed)
        val settled = arrangement.answered(recovered = false, ANSWERING, services)
        assertEquals(WatchStep.Idle, settled.next)
        assertEquals(WatchMethod.Pushed(ObserverFlavour.OPENRTM, 200.milliseconds, null), settled.method)
        assertEquals(WatchSchedule(null, 200.milliseconds), settled.schedule)
        assertEquals(
            Arranged.NOTHING,
            arrangement.answered(recovered = false, ANSWERING, services),
            "reads after settling arrange nothing",
        )
    }

    @Test
    fun `an automatic registration whose component takes no observer is polled, and says why`() {
        val arrangement = WatchArrangement()
        arrangement.needs = asking(auto)
        arrangement.reconfigured()
        arrangement.answered(recovered = false, ANSWERING, "")
        val settled = arrangement.attached(Attachment.NotOffered(emptyList()), ANSWERING)
        assertEquals(WatchStep.Idle, settled.next, "nothing attached: nothing to read again")
        assertEquals(
            WatchMethod.Polled(
                500.milliseconds,
                "it offers no ComponentObserver (sdo.service.consumer.available_services: none)",
            ),
            settled.method,
        )
        assertEquals(WatchSchedule(500.milliseconds, 1.seconds), settled.schedule)
        assertFalse(arrangement.observed)
    }

    @Test
    fun `asking for traffic detaches the observer, and attaches one that sends it`() {
        val arrangement = observing(push)
        arrangement.needs = asking(push, traffic = 100.milliseconds)
        assertEquals(WatchStep.ReadAll, arrangement.reconfigured())
        assertEquals(WatchStep.Detach, arrangement.answered(recovered = false, ANSWERING, services).next)
        assertEquals(100.milliseconds, (arrangement.detached(ANSWERING, services).next as WatchStep.Attach).traffic)
        // The same traffic asked for again keeps the observer.
        arrangement.attached(attached, ANSWERING)
        arrangement.answered(recovered = false, ANSWERING, services)
        arrangement.reconfigured()
        assertEquals(WatchStep.Idle, arrangement.answered(recovered = false, ANSWERING, services).next)
    }

    @Test
    fun `a shorter heartbeat asked for attaches the observer anew, the watchdog expecting the attached one's until then`() {
        val arrangement = observing(push)
        arrangement.needs = asking(push, EventOptions(WatchMode.PUSH, heartbeat = 100.milliseconds))
        assertEquals(WatchStep.ReadAll, arrangement.reconfigured())
        assertEquals(WatchStep.Detach, arrangement.answered(recovered = false, ANSWERING, services).next)
        assertEquals(200.milliseconds, arrangement.heartbeat, "the observer still beats as it was asked to")
        assertEquals(100.milliseconds, (arrangement.detached(ANSWERING, services).next as WatchStep.Attach).heartbeat)
        arrangement.attached(attached, ANSWERING)
        assertEquals(
            WatchSchedule(null, 100.milliseconds),
            arrangement.answered(recovered = false, ANSWERING, services).schedule,
        )
        assertEquals(100.milliseconds, arrangement.heartbeat)
        assertEquals(300.milliseconds, arrangement.silenceLimit, "three beats missed")
    }

    @Test
    fun `an observer is asked for the tree's heartbeat floor when it is longer, and the method says so`() {
        val arrangement = WatchArrangement()
        arrangement.needs = WatchNeeds(listOf(push), statesOnly = true, traffic = 1.hours, heartbeatFloor = 4.seconds)
        arrangement.reconfigured()
        val attach = arrangement.answered(recovered = false, ANSWERING, services).next as WatchStep.Attach
        assertEquals(4.seconds, attach.heartbeat)
        arrangement.attached(attached, ANSWERING)
        val settled = arrangement.answered(recovered = false, ANSWERING, services)
        assertEquals(WatchMethod.Pushed(ObserverFlavour.OPENRTM, 4.seconds, null), settled.method)
        assertEquals(WatchSchedule(null, 4.seconds), settled.schedule)
        // The floor gone (fewer components watched): attached anew at the heartbeat asked for.
        arrangement.needs = asking(push)
        arrangement.reconfigured()
        assertEquals(WatchStep.Detach, arrangement.answered(recovered = false, ANSWERING, services).next)
        assertEquals(200.milliseconds, (arrangement.detached(ANSWERING, services).next as WatchStep.Attach).heartbeat)
    }

    @Test
    fun `an unreachable component is probed at its heartbeat and what it stands behind suspected, and stays probed`() {
        val arrangement = observing(push)
        assertEquals(200.milliseconds, arrangement.expectedInterval)
        val probed = arrangement.failed(listOf(Change.Unreachable), UNREACHABLE)
        assertEquals(WatchSchedule(200.milliseconds, 200.milliseconds), probed.schedule)
        assertEquals(200.milliseconds, probed.askManagersEvery)
        assertEquals(Arranged.NOTHING, arrangement.failed(emptyList(), UNREACHABLE), "probes that fail arrange nothing")
        // A registration added meanwhile: the read it asks for fails, and the component stays probed.
        arrangement.needs = asking(push, auto)
        arrangement.reconfigured()
        val settled = arrangement.failed(emptyList(), UNREACHABLE)
        assertEquals(WatchStep.Idle, settled.next, "the observer is kept")
        assertEquals(WatchSchedule(200.milliseconds, 200.milliseconds), settled.schedule)
    }

    @Test
    fun `a component unreachable when its observer is to be attached says why it is not pushed, and stays probed`() {
        val arrangement = WatchArrangement()
        arrangement.needs = asking(push)
        arrangement.reconfigured()
        val settled = arrangement.failed(listOf(Change.Unreachable), UNREACHABLE)
        assertEquals(WatchStep.Idle, settled.next, "no observer is tried on a component that does not answer")
        assertEquals(WatchMethod.Unwatched("attaching an observer failed: it does not answer"), settled.method)
        assertEquals(
            WatchSchedule(200.milliseconds, 200.milliseconds),
            settled.schedule,
            "probed at its heartbeat until it answers",
        )
        assertEquals(200.milliseconds, settled.askManagersEvery)
    }

    @Test
    fun `the read that brings it back detaches its observer, attaches one anew, and probing ends`() {
        val arrangement = observing(push)
        arrangement.failed(listOf(Change.Unreachable), UNREACHABLE)
        val back = arrangement.answered(recovered = true, ANSWERING, services)
        assertFalse(arrangement.observed, "until attached anew, no hint announces what the read finds")
        assertEquals(WatchStep.Detach, back.next)
        assertTrue(arrangement.detached(ANSWERING, services).next is WatchStep.Attach)
        assertEquals(WatchStep.ReadAll, arrangement.attached(attached, ANSWERING).next)
        assertEquals(
            WatchSchedule(null, 200.milliseconds),
            arrangement.answered(recovered = false, ANSWERING, services).schedule,
        )
    }

    @Test
    fun `an observer attached while the component was silent is attached anew once the read after it finds it back`() {
        val arrangement = WatchArrangement()
        arrangement.needs = asking(push)
        arrangement.reconfigured()
        arrangement.answered(recovered = false, ANSWERING, services)
        arrangement.attached(attached, ANSWERING)
        assertEquals(WatchStep.Detach, arrangement.answered(recovered = true, ANSWERING, services).next)
        assertTrue(arrangement.detached(ANSWERING, services).next is WatchStep.Attach)
        arrangement.attached(attached, ANSWERING)
        assertEquals(
            WatchSchedule(null, 200.milliseconds),
            arrangement.answered(recovered = false, ANSWERING, services).schedule,
        )
        assertTrue(arrangement.observed)
    }

    @Test
    fun `a finalized component has its observer dropped and its timers stopped`() {
        val arrangement = observing(push)
        assertEquals(
            Arranged(WatchStep.Drop, WatchSchedule.OFF),
            arrangement.failed(listOf(Change.Finalized), FINALIZED),
        )
        assertFalse(arrangement.observed)
        arrangement.reconfigured()
        assertEquals(
            Arranged.NOTHING,
            arrangement.failed(emptyList(), FINALIZED),
            "nothing is arranged for a component that is gone",
        )
    }

    @Test
    fun `with no registration left the observer is detached and the timers stopped`() {
        val arrangement = observing(push)
        arrangement.needs = WatchNeeds.NONE
        assertEquals(WatchStep.Detach, arrangement.reconfigured())
        assertEquals(Arranged(schedule = WatchSchedule.OFF), arrangement.detached(ANSWERING, services))
        assertNull(arrangement.expectedInterval)
    }
}
