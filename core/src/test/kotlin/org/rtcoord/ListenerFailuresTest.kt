package org.rtcoord

import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertSame
import org.junit.jupiter.api.Test
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

class ListenerFailuresTest {
    @Test
    fun `what a Kotlin handler throws reaches the tree's failure handler, with the handler and the event`(): Unit =
        runBlocking {
            NamingService.start().use { naming ->
                Scenarios.localisation(naming.corbaloc).use {
                    val failures = LinkedBlockingQueue<ListenerFailure>()
                    RtcTree(TreeConfig(listOf(naming.address), listenerFailures = { failures += it })).use { tree ->
                        val gyro = "/${naming.address}/${RuntimeProcess.hostContext}/gyro0.rtc"
                        val handler: suspend (StateChanged) -> Unit = { event ->
                            error("handler broke on ${event.new}")
                        }
                        val subscription = tree.on(gyro, StateChanged::class.java, handler = handler)
                        try {
                            tree.component(gyro).deactivate()
                            val failure = checkNotNull(failures.poll(10, TimeUnit.SECONDS)) { "no failure reported" }
                            assertSame(handler, failure.listener)
                            assertEquals("handler broke on INACTIVE", failure.error.message)
                            assertEquals(LifeCycle.INACTIVE, (failure.event as StateChanged).new)
                        } finally {
                            subscription.cancel()
                        }
                    }
                }
            }
        }
}
