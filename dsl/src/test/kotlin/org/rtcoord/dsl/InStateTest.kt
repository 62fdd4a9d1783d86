package org.rtcoord.dsl

import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertSame
import org.junit.jupiter.api.Test
import org.rtcoord.LifeCycle.ACTIVE
import org.rtcoord.LifeCycle.ERROR
import org.rtcoord.LifeCycle.INACTIVE
import org.rtcoord.StateChanged
import org.rtcoord.fixtures.await

/** A rule on being in ERROR or entering it fires once per stay, however late its first read comes. */
class InStateTest : CoordinatedSystem() {
    @Test
    fun `a read that found ERROR drops the entry still on its way, and takes the next one`(): Unit = runBlocking {
        system.component("gyro0").fail()
        // The failure takes effect on gyro0's next execution.
        await("gyro0 to be in ERROR") { system.component("gyro0").state == RTC.LifeCycleState.ERROR_STATE }
        val gyro = tree.component(path("gyro0.rtc"))
        val reading = InState(ERROR)

        val current = reading.prepare(gyro)
        assertEquals(listOf(ERROR, ERROR), current?.let { listOf(it.old, it.new) }, "already in ERROR when read")
        assertNull(reading.translate(StateChanged(gyro, 0, ACTIVE, ERROR)), "the entry the read found")
        assertNull(reading.translate(StateChanged(gyro, 0, ERROR, INACTIVE)))
        val again = StateChanged(gyro, 0, INACTIVE, ERROR)
        assertSame(again, reading.translate(again), "a new stay")
    }

    @Test
    fun `a read that did not find ERROR takes the first entry, and each context is judged apart`(): Unit = runBlocking {
        val odometry = tree.component(path("odometry0.rtc"))
        val reading = InState(ERROR)

        assertNull(reading.prepare(odometry))
        val entered = StateChanged(odometry, 0, ACTIVE, ERROR)
        assertSame(entered, reading.translate(entered))
        val elsewhere = StateChanged(odometry, 1000, ACTIVE, ERROR)
        assertSame(elsewhere, reading.translate(elsewhere), "a participating context's own entry")
        assertNull(reading.translate(StateChanged(odometry, 0, INACTIVE, ACTIVE)))
    }
}
