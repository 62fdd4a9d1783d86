package org.rtcoord.internal.events

import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertInstanceOf
import org.junit.jupiter.api.Assertions.assertNotNull
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertSame
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.rtcoord.BecameZombie
import org.rtcoord.ComponentFinalized
import org.rtcoord.ComponentNode
import org.rtcoord.ComponentSnapshot
import org.rtcoord.EventOptions
import org.rtcoord.HeartbeatLost
import org.rtcoord.LifeCycle
import org.rtcoord.LifeCycle.ACTIVE
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.LifeCycle.INACTIVE
import org.rtcoord.LocalisationSystem
import org.rtcoord.ObserverFlavour
import org.rtcoord.RtcEvent
import org.rtcoord.StateChanged
import org.rtcoord.UnreachableException
import org.rtcoord.WatchMethod
import org.rtcoord.WatchMode
import org.rtcoord.internal.events.ComponentLiveness.Change.Finalized
import org.rtcoord.internal.events.ComponentLiveness.Change.Lost
import org.rtcoord.internal.events.ComponentLiveness.Change.Recovered
import org.rtcoord.internal.events.ComponentLiveness.Change.Unreachable
import org.rtcoord.internal.events.ComponentWatch.Timer

/**
 * The component monitor's machine, step by step on a clock the test turns (milliseconds): the timing bugs fixed in the
 * monitor, replayed as the exact sequences that showed them, and the orderings OpenRTM-aist produces (see the fixtures'
 * fidelity table). A real component gives the events their source and the reads their shape; nothing here waits.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class ComponentWatchTest {
    private val localisation = LocalisationSystem()
    private val node: ComponentNode = runBlocking { localisation.tree.component(localisation.path("laser0.rtc")) }
    private val base: ComponentSnapshot = runBlocking { node.snapshot() }

    @AfterAll fun stop() = localisation.close()

    private fun found(state: LifeCycle) =
        base.copy(contexts = base.contexts.take(1).map { it.copy(handle = 0, state = state) })

    /** A lifecycle hint that came at [at]. */
    private fun lifecycle(text: String, at: Long) = WatchInput.Hinted(Hint(HintKind.RTC_STATUS, text), at)

    private fun changed(vararg pairs: Pair<LifeCycle, LifeCycle>): List<RtcEvent> = pairs.map { (from, to) ->
        StateChanged(node, 0, from, to)
    }

    private fun stateEvents(events: List<RtcEvent>) = events.filterIsInstance<StateChanged>()

    /** Pushed, with a heartbeat every second and three beats missed at most. */
    private val pushed = EventOptions(WatchMode.PUSH, heartbeat = 1.seconds, missedBeats = 3)

    private fun asking(options: EventOptions, statesOnly: Boolean = true) =
        WatchNeeds(listOf(options), statesOnly, WatchNeeds.NO_TRAFFIC)

    /** A machine that read the component [state] at 0 ms, observed (hints expected) or polled, watched for states. */
    private fun watching(state: LifeCycle, observed: Boolean = true): ComponentWatch =
        ComponentWatch(node, 0).apply {
            needs = asking(if (observed) pushed else EventOptions(WatchMode.POLL))
            decide(listOf(WatchInput.Reconfigured), 0)
            read(found(state), 0, emptyList())
            if (observed) {
                attached(Attachment.Attached(ObserverFlavour.OPENRTM), 0)
                read(found(state), 0, emptyList())
            }
        }

    @Test
    fun `an activation is published at the read its hint asks for`() {
        val watch = watching(INACTIVE)
        val decision = watch.decide(listOf(lifecycle("ACTIVE:0", 10)), 10)
        assertEquals(setOf(0), (decision.step as WatchStep.ReadStates).handles)
        assertEquals(
            changed(INACTIVE to ACTIVE),
            stateEvents(watch.statesRead(mapOf(0 to ACTIVE), 11, emptyList()).events),
        )
    }

    @Test
    fun `a read of states keeps one snapshot per component, its last when nothing changed, else the tree's`() {
        val watch = watching(INACTIVE)
        val last = watch.last
        watch.statesRead(mapOf(0 to INACTIVE), 10, emptyList(), published = found(INACTIVE))
        assertSame(last, watch.last, "nothing changed: no copy")

        watch.decide(listOf(lifecycle("ACTIVE:0", 20)), 20)
        val published = found(ACTIVE)
        watch.statesRead(mapOf(0 to ACTIVE), 21, emptyList(), published)
        assertSame(published, watch.last, "the tree shows the same: its snapshot, not a copy")

        val elsewhere = found(ERROR)
        watch.statesRead(mapOf(0 to INACTIVE), 30, emptyList(), elsewhere)
        assertEquals(INACTIVE, watch.last!!.contexts.single().state, "the read, not what the tree shows")
    }

    @Test
    fun `while hints lead the reads, the state is read again after 1, 2, 4 ms, one recheck pending at a time`() {
        // OpenRTM-aist hints from the transition's actions, before its state machine shows the new state.
        val watch = watching(INACTIVE)
        watch.decide(listOf(lifecycle("ACTIVE:0", 0)), 0)
        val first = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList())
        assertEquals(emptyList<RtcEvent>(), first.events)
        assertEquals(listOf(Timer.RECHECK to 2L, Timer.GRACE to 501L).toSet(), first.timers.toSet())
        // A hint-driven read meanwhile arms no second recheck (4452470).
        watch.decide(listOf(WatchInput.Hinted(Hint(HintKind.CONFIGURATION, "UPDATE_CONFIGSET:default"), 1)), 1)
        assertEquals(
            emptyList<Pair<Timer, Long>>(),
            watch.read(found(INACTIVE), 1, emptyList()).timers,
            "no second recheck, no second grace read",
        )

        assertInstanceOf(
            WatchStep.ReadStates::class.java,
            watch.decide(listOf(WatchInput.Fired(Timer.RECHECK, 2)), 2).step,
        )
        assertEquals(listOf(Timer.RECHECK to 4L), watch.statesRead(mapOf(0 to INACTIVE), 2, emptyList()).timers)
        watch.decide(listOf(WatchInput.Fired(Timer.RECHECK, 4)), 4)
        assertEquals(listOf(Timer.RECHECK to 8L), watch.statesRead(mapOf(0 to INACTIVE), 4, emptyList()).timers)
        watch.decide(listOf(WatchInput.Fired(Timer.RECHECK, 8)), 8)
        assertEquals(
            changed(INACTIVE to ACTIVE),
            stateEvents(watch.statesRead(mapOf(0 to ACTIVE), 8, emptyList()).events),
        )
        assertEquals(
            WatchStep.Idle,
            watch.decide(listOf(WatchInput.Fired(Timer.GRACE, 501)), 501).step,
            "a grace read when they agree reads nothing",
        )
    }

    @Test
    fun `a change no hint announced waits for one grace read, due 500 ms after the first read that disagreed`() {
        // OpenRTM-aist announces a deactivation only when on_deactivated succeeds; it ends INACTIVE all the same.
        val watch = watching(ACTIVE)
        val first = watch.read(found(INACTIVE), 100, emptyList())
        assertEquals(emptyList<RtcEvent>(), stateEvents(first.events))
        assertEquals(listOf(Timer.GRACE to 600L), first.timers)
        // Reads while they disagree do not pile up grace reads (3236033).
        assertEquals(emptyList<Pair<Timer, Long>>(), watch.read(found(INACTIVE), 300, emptyList()).timers)
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(WatchInput.Fired(Timer.GRACE, 600)), 600).step)
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.read(found(INACTIVE), 600, emptyList()).events))
    }

    @Test
    fun `an abort, INACTIVE then ERROR hinted, is one transition and never held`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0), lifecycle("ERROR:0", 0)), 0)
        val outcome = watch.statesRead(mapOf(0 to ERROR), 1, emptyList())
        assertEquals(changed(ACTIVE to ERROR), stateEvents(outcome.events))
        assertEquals(emptyList<Pair<Timer, Long>>(), outcome.timers)
        assertNull(outcome.marker, "nothing held: no marker")
    }

    @Test
    fun `an abort reset at once, whose hints came during the read, is published as an abort (2ae9b13)`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        val late = listOf(lifecycle("ERROR:0", 1), lifecycle("INACTIVE:0", 1))
        assertEquals(
            changed(ACTIVE to ERROR, ERROR to INACTIVE),
            stateEvents(watch.statesRead(mapOf(0 to INACTIVE), 1, late).events),
        )
    }

    @Test
    fun `an abort reset at once, whose ERROR hint comes after the read, is held and then published as an abort`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        val held = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList())
        assertEquals(emptyList<RtcEvent>(), held.events, "the read overtook the ERROR hint: held")
        assertEquals(setOf(Timer.SETTLED to 2L, Timer.HOLD_LIMIT to 500L), held.timers.toSet())
        val marker = held.marker
        assertNotNull(marker, "the read that holds sends a marker")
        val decision =
            watch.decide(
                listOf(lifecycle("ERROR:0", 2), lifecycle("INACTIVE:0", 2), WatchInput.MarkerBack(marker!!)),
                2,
            )
        assertInstanceOf(WatchStep.ReadStates::class.java, decision.step)
        assertEquals(
            changed(ACTIVE to ERROR, ERROR to INACTIVE),
            stateEvents(watch.statesRead(mapOf(0 to INACTIVE), 2, emptyList()).events),
        )
        assertEquals(
            WatchStep.Idle,
            watch.decide(listOf(WatchInput.Fired(Timer.SETTLED, 2)), 3).step,
            "the hold's timer ended with it",
        )
    }

    @Test
    fun `a deactivation is held until it settled, counted from its hint, and the marker sent after its read is back`() {
        val watch = watching(ACTIVE)
        assertEquals(
            setOf(0),
            (watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0).step as WatchStep.ReadStates).handles,
        )
        val held = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList())
        assertTrue(held.events.none { it is StateChanged })
        assertEquals(
            WatchStep.Idle,
            watch.decide(listOf(WatchInput.Fired(Timer.SETTLED, 2)), 2).step,
            "settled, but its marker is not back",
        )
        assertEquals(
            WatchStep.Settle,
            watch.decide(listOf(WatchInput.MarkerBack(held.marker!!)), 3).step,
            "settled and back: published without reading again",
        )
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.settle(3, emptyList()).events))
    }

    @Test
    fun `a marker back before the hold settled waits for the settling time`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        val held = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList())
        assertEquals(
            WatchStep.Idle,
            watch.decide(listOf(WatchInput.MarkerBack(held.marker!!)), 1).step,
            "back, but not settled yet",
        )
        assertEquals(WatchStep.Settle, watch.decide(listOf(WatchInput.Fired(Timer.SETTLED, 2)), 2).step)
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.settle(2, emptyList()).events))
    }

    @Test
    fun `an abort's ERROR hint that comes as the hold settles turns it into the abort, read again`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        val held = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList())
        assertEquals(
            WatchStep.Settle,
            watch.decide(listOf(WatchInput.MarkerBack(held.marker!!), WatchInput.Fired(Timer.SETTLED, 2)), 2).step,
        )
        val settling = watch.settle(2, listOf(lifecycle("ERROR:0", 2)))
        assertEquals(
            emptyList<StateChanged>(),
            stateEvents(settling.events),
            "no deactivation once its ERROR hint is in",
        )
        assertTrue(settling.readAgain, "the hints lead past the last read: read again now")
        assertEquals(changed(ACTIVE to ERROR), stateEvents(watch.statesRead(mapOf(0 to ERROR), 3, emptyList()).events))
    }

    @Test
    fun `a deactivation whose first read found it ACTIVE still is held from the recheck that confirms it`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        // The first read found ACTIVE still (the hint came before the state showed): nothing held, no marker.
        assertNull(watch.statesRead(mapOf(0 to ACTIVE), 1, emptyList()).marker)
        watch.decide(listOf(WatchInput.Fired(Timer.RECHECK, 2)), 4)
        val held = watch.statesRead(mapOf(0 to INACTIVE), 4, emptyList())
        assertEquals(
            emptyList<StateChanged>(),
            stateEvents(held.events),
            "settled, but the hints before the read are not known to be in",
        )
        assertEquals(WatchStep.Settle, watch.decide(listOf(WatchInput.MarkerBack(held.marker!!)), 5).step)
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.settle(5, emptyList()).events))
    }

    @Test
    fun `a marker coming back ends a hold that settled, even with an earlier hold's timer still pending (83b40df)`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        val first = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList()).marker!!
        watch.decide(listOf(WatchInput.MarkerBack(first)), 1)
        // The first hold's SETTLED timer is still pending when it ends by the hold limit's read.
        watch.decide(listOf(WatchInput.Fired(Timer.HOLD_LIMIT, 500)), 500)
        watch.read(found(INACTIVE), 501, emptyList())
        watch.decide(listOf(lifecycle("ACTIVE:0", 510)), 510)
        watch.statesRead(mapOf(0 to ACTIVE), 510, emptyList())
        watch.decide(listOf(lifecycle("INACTIVE:0", 520)), 520)
        val held = watch.statesRead(mapOf(0 to INACTIVE), 521, emptyList())
        assertTrue(held.events.none { it is StateChanged })
        assertEquals(
            WatchStep.Settle,
            watch.decide(listOf(WatchInput.MarkerBack(held.marker!!)), 530).step,
            "settled and back: published at once",
        )
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.settle(530, emptyList()).events))
    }

    @Test
    fun `an earlier hold's limit, firing during a later hold, neither reads nor cuts it short`() {
        // Seen in the reaction benchmark: a deactivation 500 ms after another was held, the first hold's limit
        // fired a millisecond into the second, and its whole read put off the second's publication by 2 to 10 ms.
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        val first = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList())
        assertEquals(
            WatchStep.Settle,
            watch.decide(listOf(WatchInput.MarkerBack(first.marker!!), WatchInput.Fired(Timer.SETTLED, 2)), 2).step,
        )
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.settle(2, emptyList()).events))
        watch.decide(listOf(lifecycle("ACTIVE:0", 300)), 300)
        watch.statesRead(mapOf(0 to ACTIVE), 301, emptyList())
        watch.decide(listOf(lifecycle("INACTIVE:0", 499)), 499)
        val second = watch.statesRead(mapOf(0 to INACTIVE), 500, emptyList())
        assertEquals(
            setOf(Timer.SETTLED to 501L, Timer.HOLD_LIMIT to 999L),
            second.timers.toSet(),
            "the second hold's own timers",
        )
        assertEquals(
            WatchStep.Idle,
            watch.decide(listOf(WatchInput.Fired(Timer.HOLD_LIMIT, 500)), 500).step,
            "the first hold's limit tells nothing",
        )
        assertEquals(
            WatchStep.Settle,
            watch
                .decide(listOf(WatchInput.MarkerBack(second.marker!!), WatchInput.Fired(Timer.SETTLED, 501)), 501)
                .step,
        )
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.settle(501, emptyList()).events))
    }

    @Test
    fun `a deactivation settles counted from its hint's arrival, however late the monitor took the hint`() {
        val watch = watching(ACTIVE)
        // The monitor's thread got a core 3 ms after the hint came.
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 3)
        val held = watch.statesRead(mapOf(0 to INACTIVE), 4, emptyList())
        assertTrue(held.events.none { it is StateChanged }, "held for its marker")
        assertEquals(
            WatchStep.Settle,
            watch.decide(listOf(WatchInput.MarkerBack(held.marker!!)), 4).step,
            "settled 2 ms after the hint came: published once back",
        )
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.settle(4, emptyList()).events))
    }

    @Test
    fun `an older marker does not end a later hold, and a lost marker holds until the limit`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(lifecycle("INACTIVE:0", 0)), 0)
        val first = watch.statesRead(mapOf(0 to INACTIVE), 1, emptyList()).marker!!
        // Read again while held (a grace read, say): the hints before this read are what the hold waits for now.
        val second = watch.statesRead(mapOf(0 to INACTIVE), 3, emptyList()).marker!!
        assertTrue(first != second)
        assertEquals(
            WatchStep.Idle,
            watch.decide(listOf(WatchInput.MarkerBack(first), WatchInput.Fired(Timer.SETTLED, 2)), 10).step,
            "the first marker tells nothing of what came before the second read",
        )
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(WatchInput.Fired(Timer.HOLD_LIMIT, 500)), 500).step)
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.read(found(INACTIVE), 500, emptyList()).events))
    }

    @Test
    fun `without an observer nothing is held and no hint is awaited`() {
        val watch = watching(ACTIVE, observed = false)
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.read(found(INACTIVE), 5, emptyList()).events))
    }

    @Test
    fun `a failing on_activated is announced as ERROR alone, from INACTIVE`() {
        val watch = watching(INACTIVE)
        watch.decide(listOf(lifecycle("ERROR:0", 0)), 0)
        assertEquals(
            changed(INACTIVE to ERROR),
            stateEvents(watch.statesRead(mapOf(0 to ERROR), 1, emptyList()).events),
        )
    }

    @Test
    fun `a poll tick reads states only while they agree, and a probe that expected an older read counts as a tick`() {
        val watch = watching(INACTIVE)
        assertInstanceOf(WatchStep.ReadStates::class.java, watch.decide(listOf(WatchInput.Ticked), 100).step)
        assertTrue(watch.settled)
        val stale = WatchInput.Probed(mapOf(0 to ACTIVE), watch.epoch - 1, 7)
        assertInstanceOf(WatchStep.ReadStates::class.java, watch.decide(listOf(stale), 200).step)
        val current = WatchInput.Probed(mapOf(0 to ACTIVE), watch.epoch, 8)
        assertEquals(mapOf(0 to ACTIVE), (watch.decide(listOf(current), 300).step as WatchStep.TakeStates).states)
        watch.needs = asking(pushed, statesOnly = false)
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(WatchInput.Ticked), 400).step)
    }

    @Test
    fun `a beat overdue by a tenth is probed by a read, and silence past the limit is lost once`() {
        val watch = watching(ACTIVE)
        fun overdue(now: Long) = watch.decide(listOf(WatchInput.Overdue(heardAt = 0)), now)
        assertEquals(WatchStep.Idle, overdue(1099).step, "a heartbeat a little late is no news")
        assertEquals(
            setOf(0),
            (overdue(1100).step as WatchStep.ReadStates).handles,
            "registrations that want states alone: its states are read, as a poll's tick reads them",
        )
        // It answers: the observer alone is quiet. Reads are no heartbeats.
        watch.statesRead(mapOf(0 to ACTIVE), 1101, emptyList())
        val lost = overdue(3200)
        assertEquals(listOf(HeartbeatLost(node, 3200)), lost.events)
        assertEquals(WatchStep.ReadAll, lost.step)
        assertEquals(
            listOf(Recovered),
            watch.read(found(ACTIVE), 3201, emptyList()).changes,
            "answering again: its observer is attached anew",
        )
    }

    @Test
    fun `a beat overdue is probed by a whole read when a registration wants more than states`() {
        val watch = watching(ACTIVE)
        watch.needs = asking(pushed, statesOnly = false)
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(WatchInput.Overdue(heardAt = 0)), 1100).step)
    }

    @Test
    fun `a refused call tells the silence only when a beat was missed, never a silence of a millisecond`() {
        val refused = UnreachableException("laser0.rtc", org.omg.CORBA.TRANSIENT("connection refused"))
        val killed = watching(ACTIVE)
        killed.decide(listOf(WatchInput.Overdue(heardAt = 0)), 1100)
        val outcome = killed.failed(refused, 1101)
        assertEquals(listOf(HeartbeatLost(node, 1101), BecameZombie(node, refused)), outcome.events)
        assertEquals(listOf(Lost(1101), Unreachable), outcome.changes)

        val suspected = watching(ACTIVE)
        suspected.decide(listOf(lifecycle("ACTIVE:0", 500)), 500)
        assertEquals(listOf(BecameZombie(node, refused)), suspected.failed(refused, 501).events)
        assertEquals(emptyList<RtcEvent>(), suspected.failed(refused, 700).events, "probes that fail are no news")
        assertEquals(
            WatchStep.ReadAll,
            suspected.decide(listOf(lifecycle("ACTIVE:0", 800)), 800).step,
            "a hint does not bring it back: a whole read does",
        )
    }

    @Test
    fun `a component that does not answer is probed by its poll at each beat, not at every watchdog check`() {
        val watch = watching(ACTIVE)
        watch.decide(listOf(WatchInput.Overdue(heardAt = 0)), 1100)
        val failed =
            watch.failed(UnreachableException("laser0.rtc", org.omg.CORBA.TRANSIENT("connection refused")), 1101)
        assertEquals(1.seconds, failed.arranged.schedule?.pollPeriod, "probed at its heartbeat")
        // The watchdog still checks ten times a beat: the heartbeats it waits for are those of the component's return.
        val checks = (1..20).map { watch.decide(listOf(WatchInput.Overdue(heardAt = 0)), 1101 + it * 100L).step }
        assertEquals(0, checks.count { it != WatchStep.Idle }, "reads the watchdog asked for in two beats")
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(WatchInput.Ticked), 2101).step, "the poll's tick probes it")
    }

    @Test
    fun `the read that brings it back publishes what it finds at once, as no hint announced it`() {
        val watch = watching(ACTIVE)
        watch.failed(UnreachableException("laser0.rtc", org.omg.CORBA.TRANSIENT()), 100)
        val back = watch.read(found(INACTIVE), 200, emptyList())
        assertEquals(listOf(Recovered), back.changes)
        assertEquals(
            WatchStep.Detach,
            back.arranged.next,
            "a component back may have dropped its observer: it is attached anew",
        )
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(back.events))
    }

    @Test
    fun `a component that announced FINALIZE and then cannot be reached is finalized`() {
        val watch = watching(INACTIVE)
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(lifecycle("FINALIZE:0", 10)), 10).step)
        val outcome = watch.failed(UnreachableException("laser0.rtc", org.omg.CORBA.COMM_FAILURE()), 11)
        assertEquals(listOf(ComponentFinalized(node)), outcome.events)
        assertEquals(listOf(Finalized), outcome.changes)
        assertEquals(Arranged(WatchStep.Drop, WatchSchedule.OFF), outcome.arranged)
        assertEquals(
            WatchStep.Idle,
            watch.decide(listOf(WatchInput.Ticked), 12).step,
            "nothing is read once it is gone",
        )
    }

    @Test
    fun `when the registrations change it reads, attaches an observer, reads again, and then says how it is watched`() {
        val watch = ComponentWatch(node, 0)
        watch.needs = asking(pushed)
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(WatchInput.Ticked, WatchInput.Reconfigured), 0).step)
        val attach = watch.read(found(INACTIVE), 1, emptyList()).arranged.next as WatchStep.Attach
        assertEquals(base.properties["sdo.service.consumer.available_services"], attach.advertised)
        assertEquals(WatchStep.ReadAll, watch.attached(Attachment.Attached(ObserverFlavour.OPENRTM), 2).arranged.next)
        val settled = watch.read(found(INACTIVE), 3, emptyList())
        assertEquals(WatchMethod.Pushed(ObserverFlavour.OPENRTM, 1.seconds, null), settled.arranged.method)
        assertEquals(WatchSchedule(null, 1.seconds), settled.arranged.schedule)
        assertEquals(WatchStep.Idle, settled.arranged.next)
    }

    @Test
    fun `a change whose hint went to the observer before is found by reading again a grace period after attaching`() {
        // EventsTest's hung component (a busy-loop run): back, its old observer detached and a new one attached while
        // a deactivation was under way; the read after attaching found ACTIVE, and the hint went to the old observer.
        val watch = watching(ACTIVE)
        watch.failed(UnreachableException("laser0.rtc", org.omg.CORBA.TRANSIENT()), 100)
        assertEquals(WatchStep.Detach, watch.read(found(ACTIVE), 200, emptyList()).arranged.next)
        assertInstanceOf(WatchStep.Attach::class.java, watch.detached().arranged.next)
        assertEquals(WatchStep.ReadAll, watch.attached(Attachment.Attached(ObserverFlavour.OPENRTM), 210).arranged.next)
        val reread = watch.read(found(ACTIVE), 220, emptyList())
        assertEquals(listOf(Timer.CONFIRM to 720L), reread.timers)
        assertEquals(WatchStep.Idle, reread.arranged.next)
        val confirming = watch.decide(listOf(WatchInput.Fired(Timer.CONFIRM, 720)), 720).step
        assertEquals(setOf(0), (confirming as WatchStep.ReadStates).handles)
        val confirmed = watch.statesRead(mapOf(0 to INACTIVE), 721, emptyList())
        assertEquals(listOf(Timer.GRACE to 1221L), confirmed.timers, "no hint announced it: a grace read decides")
        assertEquals(WatchStep.ReadAll, watch.decide(listOf(WatchInput.Fired(Timer.GRACE, 1221)), 1221).step)
        assertEquals(changed(ACTIVE to INACTIVE), stateEvents(watch.read(found(INACTIVE), 1222, emptyList()).events))
    }
}
