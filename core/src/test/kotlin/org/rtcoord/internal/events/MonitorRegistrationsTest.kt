package org.rtcoord.internal.events

import java.util.concurrent.atomic.AtomicBoolean
import kotlin.concurrent.thread
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.Overlap
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig

/**
 * What a monitor's registrations ask of it is read while registrations come and go on other threads: exploring faults
 * found a monitor that failed there ("Index 0 out of bounds for length 0") as a scenario's tree closed.
 */
class MonitorRegistrationsTest {
    @Test
    fun `what they ask is read while one comes and goes`() =
        RtcTree(TreeConfig()).use { tree ->
            val registrations = MonitorRegistrations()
            val sink = EventSink(tree.core.scope, { true }, Overlap.QUEUE, {})
            val one = MonitorRegistration(sink, EventOptions(), false, statesOnly = true)
            val stop = AtomicBoolean()
            val churn = thread {
                while (!stop.get()) {
                    registrations += one
                    registrations -= one
                }
            }
            try {
                repeat(200_000) {
                    val needs = registrations.needs()
                    assertTrue(needs.options.size <= 1)
                }
            } finally {
                stop.set(true)
                churn.join()
            }
        }
}
