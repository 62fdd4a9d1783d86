package org.rtcoord

import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Test
import org.rtcoord.LifeCycle.ACTIVE
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.LifeCycle.INACTIVE
import org.rtcoord.internal.events.ContextPhase.Agreed
import org.rtcoord.internal.events.ContextPhase.Disagreeing
import org.rtcoord.internal.events.ContextPhase.Held
import org.rtcoord.internal.events.ContextPhase.Leading
import org.rtcoord.internal.events.Hint
import org.rtcoord.internal.events.HintKind
import org.rtcoord.internal.events.StateTracker

/** Hints are untrusted: the reconciliation never emits a phantom and always ends in the real state. */
class StateTrackerTest {
    private val grace = 250L

    @Test
    fun `hinted transitions confirmed by a read are all published`() {
        val tracker = StateTracker(ACTIVE)
        listOf(INACTIVE, ACTIVE, INACTIVE).forEach { tracker.hint(it, 0) }
        assertEquals(
            listOf(ACTIVE to INACTIVE, INACTIVE to ACTIVE, ACTIVE to INACTIVE),
            tracker.reconcile(INACTIVE, 1, grace, hintsExpected = true),
        )
    }

    @Test
    fun `an abort announced as INACTIVE then ERROR is one transition`() {
        val tracker = StateTracker(ACTIVE)
        tracker.hint(INACTIVE, 0)
        tracker.hint(ERROR, 0)
        assertEquals(listOf(ACTIVE to ERROR), tracker.reconcile(ERROR, 1, grace, hintsExpected = true))
    }

    @Test
    fun `a hinted deactivation waits for an abort's ERROR hint, until the hints before it are in or the limit after its hint`() {
        val tracker = StateTracker(ACTIVE, holdLimitMillis = 25)
        tracker.hint(INACTIVE, 100)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 101, grace, hintsExpected = true),
            "held",
        )
        assertEquals(Held(100, flushed = false), tracker.phase)
        tracker.hint(ERROR, 105)
        tracker.hint(INACTIVE, 106)
        assertEquals(
            listOf(ACTIVE to ERROR, ERROR to INACTIVE),
            tracker.reconcile(INACTIVE, 110, grace, hintsExpected = true),
            "an abort reset at once",
        )

        tracker.hint(ACTIVE, 120)
        assertEquals(
            listOf(INACTIVE to ACTIVE),
            tracker.reconcile(ACTIVE, 120, grace, hintsExpected = true),
            "other transitions are not held",
        )
        tracker.hint(INACTIVE, 130)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 131, grace, hintsExpected = true),
        )
        assertEquals(Held(130, flushed = false), tracker.phase, "the limit counts from the hint")
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 154, grace, hintsExpected = true),
        )
        assertEquals(
            listOf(ACTIVE to INACTIVE),
            tracker.reconcile(INACTIVE, 155, grace, hintsExpected = true),
            "a deactivation at the limit",
        )
        assertEquals(Agreed, tracker.phase)

        tracker.hint(ACTIVE, 160)
        assertEquals(listOf(INACTIVE to ACTIVE), tracker.reconcile(ACTIVE, 160, grace, hintsExpected = true))
        tracker.hint(INACTIVE, 161)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 161, grace, hintsExpected = true),
        )
        tracker.flushed()
        assertEquals(
            listOf(ACTIVE to INACTIVE),
            tracker.reconcile(INACTIVE, 162, grace, hintsExpected = true),
            "a deactivation once the earlier hints are in",
        )
        assertEquals(Agreed, tracker.phase)
        tracker.flushed()
        tracker.hint(ACTIVE, 163)
        tracker.reconcile(ACTIVE, 163, grace, hintsExpected = true)
        tracker.hint(INACTIVE, 164)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 164, grace, hintsExpected = true),
            "a flush before the hint does not end its hold",
        )
    }

    @Test
    fun `a held deactivation ends once it has settled, counted from its hint, and the hints before it are in, whichever comes last`() {
        val tracker = StateTracker(ACTIVE, holdLimitMillis = 500, settleMillis = 3)
        tracker.hint(INACTIVE, 100)
        tracker.flushed()
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 101, grace, hintsExpected = true),
            "held",
        )
        assertEquals(
            Held(100, flushed = false),
            tracker.phase,
            "a marker back before the hold began tells nothing of the hints before its read",
        )
        tracker.flushed()
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 102, grace, hintsExpected = true),
            "the hints are in, but it has not settled",
        )
        assertEquals(Held(100, flushed = true), tracker.phase)
        tracker.hint(ERROR, 102)
        tracker.hint(INACTIVE, 102)
        assertEquals(
            listOf(ACTIVE to ERROR, ERROR to INACTIVE),
            tracker.reconcile(INACTIVE, 102, grace, hintsExpected = true),
            "an ERROR hint late behind the marker",
        )
        assertEquals(Agreed, tracker.phase)

        tracker.hint(ACTIVE, 120)
        tracker.reconcile(ACTIVE, 120, grace, hintsExpected = true)
        tracker.hint(INACTIVE, 130)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 134, grace, hintsExpected = true),
            "settled, but the hints before it are not known to be in",
        )
        assertEquals(Held(130, flushed = false), tracker.phase)
        tracker.flushed()
        assertEquals(
            listOf(ACTIVE to INACTIVE),
            tracker.reconcile(INACTIVE, 135, grace, hintsExpected = true),
            "a deactivation",
        )
        assertEquals(Agreed, tracker.phase)
    }

    @Test
    fun `hints lead a read that finds the state they left, not one that finds a change they did not announce`() {
        val tracker = StateTracker(ACTIVE)
        tracker.hint(INACTIVE, 0)
        // OpenRTM-aist shows the new state only once the transition's hints are sent: a read may come first.
        assertEquals(emptyList<Pair<LifeCycle, LifeCycle>>(), tracker.reconcile(ACTIVE, 1, grace, hintsExpected = true))
        assertEquals(Leading(1), tracker.phase)
        assertEquals(listOf(ACTIVE to INACTIVE), tracker.reconcile(INACTIVE, 2, grace, hintsExpected = true))
        assertEquals(Agreed, tracker.phase)

        // A read ahead of the hints waits for them; reading again sooner would not help.
        assertEquals(emptyList<Pair<LifeCycle, LifeCycle>>(), tracker.reconcile(ACTIVE, 3, grace, hintsExpected = true))
        assertEquals(Disagreeing(3), tracker.phase)
    }

    @Test
    fun `a hint no read confirms is dropped after the grace period`() {
        val tracker = StateTracker(INACTIVE)
        tracker.hint(ACTIVE, 0)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 10, grace, hintsExpected = true),
            "waits for later hints",
        )
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 10 + grace, grace, hintsExpected = true),
            "a spoofed ACTIVE leaves no phantom",
        )
        assertEquals(INACTIVE, tracker.confirmed)
    }

    @Test
    fun `duplicates and impossible transitions are ignored, and the read wins`() {
        val tracker = StateTracker(INACTIVE)
        tracker.hint(INACTIVE, 0)
        tracker.hint(ACTIVE, 0)
        tracker.hint(ACTIVE, 0)
        assertEquals(listOf(INACTIVE to ACTIVE), tracker.reconcile(ACTIVE, 1, grace, hintsExpected = true))
        val erroneous = StateTracker(ERROR)
        erroneous.hint(ACTIVE, 0)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            erroneous.reconcile(INACTIVE, 1, grace, hintsExpected = true),
            "waits for the hint of the change read",
        )
        assertEquals(
            listOf(ERROR to INACTIVE),
            erroneous.reconcile(INACTIVE, 1 + grace, grace, hintsExpected = true),
            "ERROR to ACTIVE is impossible: the read decides",
        )
    }

    @Test
    fun `without an observer a read that differs is a transition at once`() {
        val tracker = StateTracker(ACTIVE)
        assertEquals(listOf(ACTIVE to ERROR), tracker.reconcile(ERROR, 0, grace, hintsExpected = false))
        assertEquals(emptyList<Pair<LifeCycle, LifeCycle>>(), tracker.reconcile(ERROR, 0, grace, hintsExpected = false))
    }

    @Test
    fun `a change a read finds before its hints waits for them, so late hints announce it once`() {
        val tracker = StateTracker(ACTIVE)
        assertEquals(emptyList<Pair<LifeCycle, LifeCycle>>(), tracker.reconcile(ERROR, 0, grace, hintsExpected = true))
        // The abort's hints arrive after the read: one transition, not ACTIVE to ERROR and then ERROR to INACTIVE to
        // ERROR.
        tracker.hint(INACTIVE, 0)
        tracker.hint(ERROR, 0)
        assertEquals(listOf(ACTIVE to ERROR), tracker.reconcile(ERROR, 100, grace, hintsExpected = true))
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(ERROR, 200, grace, hintsExpected = true),
        )
    }

    @Test
    fun `a change no hint announces is published once the grace period after the first read that found it is over`() {
        val tracker = StateTracker(ACTIVE)
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 1000, grace, hintsExpected = true),
        )
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 1000 + grace - 1, grace, hintsExpected = true),
        )
        assertEquals(listOf(ACTIVE to INACTIVE), tracker.reconcile(INACTIVE, 1000 + grace, grace, hintsExpected = true))
        assertEquals(Agreed, tracker.phase)
    }

    @Test
    fun `a hint turns a disagreement into hints leading, and an ERROR hint a read does not show yet ends a hold`() {
        val tracker = StateTracker(ACTIVE, holdLimitMillis = 500, settleMillis = 2)
        tracker.reconcile(INACTIVE, 10, grace, hintsExpected = true)
        assertEquals(Disagreeing(10), tracker.phase, "a change no hint announced")
        tracker.hint(INACTIVE, 11)
        assertEquals(
            Leading(10),
            tracker.phase,
            "its hint came: the grace period still counts from the read that disagreed",
        )
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 12, grace, hintsExpected = true),
        )
        assertEquals(Held(11, flushed = false), tracker.phase, "a hinted deactivation confirmed: held from its hint")
        tracker.flushed()
        tracker.hint(ERROR, 13)
        assertEquals(Held(11, flushed = true), tracker.phase, "a hint alone changes no hold: the read it asks for does")
        assertEquals(
            emptyList<Pair<LifeCycle, LifeCycle>>(),
            tracker.reconcile(INACTIVE, 14, grace, hintsExpected = true),
        )
        assertEquals(Leading(14), tracker.phase, "an abort whose ERROR the read does not show yet")
        assertEquals(listOf(ACTIVE to ERROR), tracker.reconcile(ERROR, 15, grace, hintsExpected = true))

        tracker.hint(INACTIVE, 20)
        tracker.hint(ACTIVE, 20)
        tracker.hint(INACTIVE, 21)
        tracker.reconcile(INACTIVE, 22, grace, hintsExpected = true)
        tracker.flushed()
        tracker.hint(ACTIVE, 23)
        tracker.hint(INACTIVE, 24)
        assertEquals(
            Held(21, flushed = false),
            tracker.phase,
            "another deactivation hinted in the hold waits for a marker of its own",
        )
    }

    @Test
    fun `hints are parsed leniently and malformed ones name nothing`() {
        assertEquals(ACTIVE to 0, Hint(HintKind.RTC_STATUS, " active : 0 ").lifeCycle())
        assertEquals(ERROR to 1000, Hint(HintKind.RTC_STATUS, "ERROR:1000").lifeCycle())
        listOf("", "ACTIVE", "ACTIVE:x", "RUNNING:0", "ACTIVE:0:1").forEach {
            assertEquals(null, Hint(HintKind.RTC_STATUS, it).lifeCycle(), it)
        }
        assertEquals(true, Hint(HintKind.RTC_STATUS, "FINALIZE:0").isFinalize)
    }
}
