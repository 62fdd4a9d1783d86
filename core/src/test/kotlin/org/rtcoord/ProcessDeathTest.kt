package org.rtcoord

import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.atomic.AtomicReference
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.naming.NamingService

/**
 * A process that dies is noticed promptly: the paper's system in a fixture process of its own (a manager and four
 * components) is SIGKILLed while a tree watches it by push at 1 s heartbeats. A beat overdue has each component read,
 * and the refused connection says it is gone: every component is reported within 1.5 s, each with why, and none with a
 * silence shorter than a beat.
 */
class ProcessDeathTest {
    @Test
    fun `every component of a SIGKILLed process is reported within one and a half heartbeats, each saying why`(): Unit =
        runBlocking {
            NamingService.start().use { naming ->
                FixtureProcess.start("--naming", naming.address, "--scenario", "localisation").use { process ->
                    RtcTree(TreeConfig(listOf(naming.address))).use { tree ->
                        val host = "/${naming.address}/${RuntimeProcess.hostContext}"
                        val names = listOf("laser0.rtc", "gyro0.rtc", "odometry0.rtc", "laser_localise0.rtc")
                        val gone = ConcurrentHashMap<String, Long>()
                        val events = ConcurrentLinkedQueue<RtcEvent>()
                        val killed = AtomicReference<TimeSource.Monotonic.ValueTimeMark>()
                        tree.on(host, RtcEvent::class.java, EventOptions(WatchMode.PUSH, heartbeat = 1.seconds)) { event
                            ->
                            events += event
                            val since = killed.get()
                            if (event is BecameZombie && since != null)
                                gone.putIfAbsent(event.source.name, since.elapsedNow().inWholeMilliseconds)
                        }
                        await("an observer on every component", 10.seconds) {
                            events.count { it is WatchMethodChanged && it.new is WatchMethod.Pushed } >= names.size
                        }
                        killed.set(TimeSource.Monotonic.markNow())
                        process.kill()
                        val bound = 1500.milliseconds
                        await("every component reported", 10.seconds) { names.all { gone.containsKey(it) } }
                        val reported = names.associateWith { gone.getValue(it) }
                        println("SIGKILL to BecameZombie, by component (ms): $reported")
                        val zombies = events.filterIsInstance<BecameZombie>()
                        zombies.forEach { println("${it.source.name}: ${it.cause.reason}") }
                        assertTrue(
                            reported.values.all { it <= bound.inWholeMilliseconds },
                            "every component within $bound: $reported",
                        )
                        assertEquals(names.toSet(), zombies.map { it.source.name }.toSet())
                        assertTrue(zombies.all { it.cause is UnreachableException }, "each says it cannot be reached")
                        val silences = events.filterIsInstance<HeartbeatLost>().map { it.silentMillis }
                        assertTrue(silences.all { it >= 1000 }, "no silence shorter than a beat: $silences")
                    }
                }
            }
        }
}
