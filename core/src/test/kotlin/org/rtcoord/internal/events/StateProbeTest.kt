package org.rtcoord.internal.events

import RTC.RTObject
import RTC.RTObjectHelper
import java.util.concurrent.CompletableFuture
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertInstanceOf
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.LifeCycle
import org.rtcoord.fixtures.await
import org.rtcoord.internal.AsyncRequests
import org.rtcoord.runtime.RuntimeComponent
import org.rtcoord.runtime.RuntimeOrb
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/** The poll read that needs no thread and no monitor, over real IIOP to a fixture component. */
class StateProbeTest {
    private val naming = NamingService.start()
    private val runtime = RuntimeProcess.start(naming.corbaloc)
    private val client = RuntimeOrb.start()
    private val scope = CoroutineScope(SupervisorJob())
    private val requests = AsyncRequests(client::poa, scope)

    private val fixture: RuntimeComponent = runtime.create(Scenarios.relay, "subject0").also { it.activate() }
    private val component: RTObject =
        RTObjectHelper.narrow(client.orb.string_to_object(client.orb.object_to_string(fixture.ref)))
    private val context = component.get_owned_contexts().single()

    private val answered = AtomicInteger()
    private val outcomes = LinkedBlockingQueue<StateProbe.Outcome>()
    private val probe = StateProbe(requests, component, { 0L }, { answered.incrementAndGet() }) { outcomes += it }

    @AfterEach
    fun stop() {
        probe.close()
        scope.cancel()
        client.close()
        runtime.close()
        naming.close()
    }

    private fun expect(state: LifeCycle, epoch: Long = 1) =
        probe.expect(StateProbe.Expectation(listOf(0 to context), listOf(state), epoch))

    /** Sends a probe and returns what ends it. */
    private fun send(): CompletableFuture<Unit> {
        val done = CompletableFuture<Unit>()
        assertTrue(probe.send { done.complete(Unit) })
        return done
    }

    @Test
    fun `a probe that finds the expected states ends there, without the monitor`() {
        expect(LifeCycle.ACTIVE)
        repeat(3) { send().get(5, TimeUnit.SECONDS) }

        assertEquals(3, answered.get())
        // A round ends answered or handed over, never both: with all three done, none can be handed over later.
        assertTrue(outcomes.isEmpty())
    }

    @Test
    fun `states other than expected go to the monitor, as of the expectation's epoch`() {
        expect(LifeCycle.INACTIVE, epoch = 7)
        val done = send()

        val changed = assertInstanceOf(StateProbe.Outcome.Changed::class.java, outcomes.poll(5, TimeUnit.SECONDS))
        assertEquals(mapOf(0 to LifeCycle.ACTIVE), changed.states)
        assertEquals(7, changed.epoch)
        // The monitor says when it is done with it.
        assertFalse(done.isDone)
        changed.done()
        assertTrue(done.isDone)
        assertEquals(0, answered.get())
    }

    @Test
    fun `a failed request is handed over unsettled`() {
        expect(LifeCycle.ACTIVE)
        runtime.close()
        // A call of our own sees the process gone first. Otherwise the probe may go out on the old connection
        // before the client has read its close, and JacORB drops an asynchronous request lost with its connection
        // without a word (ReplyReceiver ignores the connection's cancel): that case is late()'s, tested below.
        assertTrue(runCatching { component.get_owned_contexts() }.isFailure, "the process is gone")

        assertTrue(probe.send {})
        assertInstanceOf(StateProbe.Outcome.Unsettled::class.java, outcomes.poll(5, TimeUnit.SECONDS))
    }

    @Test
    fun `a probe unanswered at its next turn is handed over, and its late reply is ignored`() {
        expect(LifeCycle.ACTIVE)
        fixture.hang()
        send()
        await("the request held by the hung component") { fixture.heldCalls == 1 }
        assertTrue(outcomes.isEmpty())
        probe.late()
        assertInstanceOf(StateProbe.Outcome.Unsettled::class.java, outcomes.poll(5, TimeUnit.SECONDS))

        fixture.release()
        await("the held request let through") { fixture.heldCalls == 0 }
        // Its reply goes out now, ahead of two more probes on the same connection, each on a fresh handler: those two
        // are answered, and the late one counts for nothing.
        repeat(2) { send().get(5, TimeUnit.SECONDS) }
        assertEquals(2, answered.get())
        assertTrue(outcomes.isEmpty())
    }

    @Test
    fun `without an expectation the monitor takes the tick`() {
        probe.expect(null)
        assertFalse(probe.send {})
    }
}
