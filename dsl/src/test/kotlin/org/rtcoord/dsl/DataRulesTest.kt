package org.rtcoord.dsl

import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.milliseconds
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.RtcTree
import org.rtcoord.TimedDouble
import org.rtcoord.TimedDoubleSeq
import org.rtcoord.TreeConfig
import org.rtcoord.WatchMode
import org.rtcoord.fixtures.await
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * Data rules against the fixtures' real data flow: samples by type, LATEST overlap, rate floors, taps shared and
 * removed.
 */
class DataRulesTest {
    private val naming = NamingService.start()
    private val system = Scenarios.localisation(naming.corbaloc)
    private val config = TreeConfig(nameServers = listOf(naming.address))
    private val tree = RtcTree(config)
    private val witness = RtcTree(config)
    private val log = ConcurrentLinkedQueue<String>()

    @AfterEach
    fun stop() {
        tree.close()
        witness.close()
        system.close()
        naming.close()
    }

    private fun coordinator(declare: Coordination.() -> Unit): Coordinator =
        Coordinator(tree, Coordination(emptyList(), config).apply(declare), EventOptions(WatchMode.PUSH)) { log += it }

    private fun taps(port: String): Int = runBlocking {
        witness.port("/${naming.address}/${org.rtcoord.runtime.RuntimeProcess.hostContext}/$port").connections().count {
            it.id.startsWith("rtcoord-tap-")
        }
    }

    @Test
    fun `data rules get the samples of their type, only the newest waiting behind a slow handler, over one shared tap`():
        Unit = runBlocking {
        val gyro = ConcurrentLinkedQueue<Double>()
        val handled = AtomicInteger()
        val wrongType = AtomicInteger()
        coordinator {
            on(port("gyro0.rtc:gyro")).data<TimedDouble> { sample -> gyro += sample.data }
            on(port("gyro0.rtc:gyro")).data<TimedDoubleSeq> { wrongType.incrementAndGet() }
            on(port("laser0.rtc:laser")).data<TimedDoubleSeq> {
                handled.incrementAndGet()
                delay(200.milliseconds)
            }
        }
            .use { coordinator ->
                coordinator.start()
                assertEquals(1, taps("gyro0.rtc:gyro"), "two rules on the gyro share one tap")
                await("gyro samples") { gyro.size >= 20 }
                assertTrue(gyro.all { it in 0.0..1.0 }, "the gyro writes 0.01 * (tick % 100): ${gyro.take(5)}")
                val started = System.nanoTime()
                await("a second of the slow handler") { System.nanoTime() - started > 1_000_000_000 }
                // At 100 Hz a queue would hold every scan; LATEST runs the handler about every 200 ms.
                assertTrue(handled.get() in 3..8, "the slow handler ran ${handled.get()} times")
                assertEquals(0, wrongType.get())
                coordinator.close()
                await("the coordinator's taps removed when it closes") {
                    taps("gyro0.rtc:gyro") == 0 && taps("laser0.rtc:laser") == 0
                }
            }
    }

    @Test
    fun `rateBelow fires once for a port under its floor and never for one above it, and silentFor while ACTIVE`():
        Unit = runBlocking {
        val slow = ConcurrentLinkedQueue<Double>()
        val fine = AtomicInteger()
        val silent = AtomicInteger()
        coordinator {
            on(port("odometry0.rtc:odo")).rateBelow(500.0) { rate -> slow += rate }
            on(port("odometry0.rtc:odo")).rateBelow(5.0) { fine.incrementAndGet() }
            on(port("gyro0.rtc:gyro")).silentFor(300.milliseconds) { silent.incrementAndGet() }
        }
            .use { coordinator ->
                coordinator.start()
                await("the odometry's rate (100 Hz) reported below 500 Hz") { slow.isNotEmpty() }
                assertTrue(slow.single() in 20.0..150.0, "measured ${slow.single()} Hz")
                system.component("gyro0").deactivate()
                val deactivated = System.nanoTime()
                await("a second with the gyro INACTIVE") { System.nanoTime() - deactivated > 1_000_000_000 }
                assertEquals(0, silent.get(), "an INACTIVE component's silence does not count")
                system.component("gyro0").activate()
                system.component("gyro0").freezeOutput()
                await("the gyro's silence while ACTIVE") { silent.get() == 1 }
                assertEquals(1, slow.size, "once per drop")
                assertEquals(0, fine.get())
                assertEquals(0, coordinator.failures)
            }
    }

    @Test
    fun `a data rule follows its component when it is re-created, tapping the new one`(): Unit = runBlocking {
        val samples = AtomicInteger()
        coordinator {
            on(port("gyro0.rtc:gyro")).data<TimedDouble> { samples.incrementAndGet() }
        }
            .use { coordinator ->
                coordinator.start()
                await("samples from the first gyro0") { samples.get() > 0 }
                val host = "/${naming.address}/${org.rtcoord.runtime.RuntimeProcess.hostContext}"
                witness.component("$host/gyro0.rtc").exit()
                await("gyro0 to be gone") { system.runtime.components.none { it.instanceName == "gyro0" } }
                witness.manager("$host/manager.mgr").create("gyro", "gyro0")
                system.component("gyro0").activate()
                await("the rule to tap the new gyro0") { taps("gyro0.rtc:gyro") == 1 }
                val before = samples.get()
                await("samples from the new gyro0") { samples.get() > before }
                assertEquals(0, coordinator.failures, log.toString())
            }
    }
}
