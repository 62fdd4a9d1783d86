package org.rtcoord

import java.time.Instant
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlin.time.TimeSource
import kotlin.time.toJavaDuration
import kotlinx.coroutines.flow.take
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.runPeer

/** Data taps and traffic events against the fixtures' real corba_cdr data flow. */
class DataTapTest {
    private val localisation = LocalisationSystem()
    private val tree
        get() = localisation.tree

    @AfterEach fun close() = localisation.close()

    /** The connector ids `rtcat -ll component.rtc:port` shows for taps. */
    private fun tapConnectors(component: String, port: String): List<String> =
        runPeer("rtcat", "-ll", localisation.path("$component.rtc") + ":$port")
            .ok()
            .output
            .lines()
            .map { it.trim() }
            .filter { it.startsWith("ID") && it.contains("rtcoord-tap-") }

    private fun samples(port: Port): Pair<Subscription, LinkedBlockingQueue<PortData>> = runBlocking {
        val queue = LinkedBlockingQueue<PortData>()
        port.tap { queue += it } to queue
    }

    @Test
    fun `a tap decodes the laser's scans with their time stamps, and rtcat shows its connector only while it exists`():
        Unit = runBlocking {
        val port = tree.port(localisation.path("laser0.rtc:laser"))
        val before = Instant.now().minusSeconds(1)
        val (subscription, queue) = samples(port)
        val scan = queue.poll(5, TimeUnit.SECONDS) as TimedDoubleSeq
        assertEquals(8, scan.data.size)
        assertTrue(scan.data.all { it in 4.0..6.0 }, "the laser writes 4 + (tick + i) % 3: ${scan.data}")
        assertTrue(
            scan.time.isAfter(before) && scan.time.isBefore(Instant.now().plusSeconds(1)),
            "stamped now: ${scan.time}",
        )

        val shown = tapConnectors("laser0", "laser")
        assertEquals(1, shown.size, "rtcat -ll shows one tap connector: $shown")
        val listed = runPeer("rtcat", "-l", localisation.path("laser0.rtc:laser")).ok().output
        assertEquals(
            2,
            Regex("Connected to").findAll(listed).count(),
            "rtcat -l lists the localiser's connection and the tap's:\n$listed",
        )
        assertTrue(
            port.connections().any {
                it.id.startsWith("rtcoord-tap-") && it.name.startsWith("rtcoord-tap-laser0.laser")
            }
        )
        assertTrue(
            localisation.system.component("laser_localise0").latest("laser") != null,
            "the real connection still flows",
        )

        subscription.cancel()
        await("the tap connector removed", 10.seconds) {
            port.runCatchingConnections().none { it.id.startsWith("rtcoord-tap-") }
        }
        assertEquals(emptyList<String>(), tapConnectors("laser0", "laser"), "rtcat -ll no longer shows it")
        assertEquals(
            1,
            Regex("Connected to")
                .findAll(runPeer("rtcat", "-l", localisation.path("laser0.rtc:laser")).ok().output)
                .count(),
        )
    }

    @Test
    fun `listeners of one port share one tap, which goes with the last of them and with the tree`(): Unit =
        runBlocking {
            val port = tree.port(localisation.path("odometry0.rtc:odo"))
            val (first, firstQueue) = samples(port)
            val (second, secondQueue) = samples(port)
            assertTrue(firstQueue.poll(5, TimeUnit.SECONDS) is TimedDoubleSeq)
            assertTrue(secondQueue.poll(5, TimeUnit.SECONDS) is TimedDoubleSeq)
            assertEquals(1, port.connections().count { it.id.startsWith("rtcoord-tap-") }, "one tap for both listeners")

            first.cancel()
            secondQueue.clear()
            assertTrue(secondQueue.poll(5, TimeUnit.SECONDS) is TimedDoubleSeq, "the other listener still receives")
            assertEquals(1, port.connections().count { it.id.startsWith("rtcoord-tap-") })
            second.cancel()
            await("the tap removed with its last listener") {
                port.runCatchingConnections().none { it.id.startsWith("rtcoord-tap-") }
            }

            val flowed = withTimeout(5.seconds) { port.data().take(3).toList() }
            assertEquals(3, flowed.size)
            await("the flow's tap removed once the flow ends") {
                port.runCatchingConnections().none { it.id.startsWith("rtcoord-tap-") }
            }

            samples(port)
            tree.close()
            assertEquals(emptyList<String>(), tapConnectors("odometry0", "odo"), "closing the tree removed its tap")
        }

    @Test
    fun `a restarted tree removes the tap connector its crashed predecessor left, and no live tree's`(): Unit =
        runBlocking {
            val path = localisation.path("gyro0.rtc:gyro")
            val crashed = RtcTree(TreeConfig(listOf(localisation.naming.address)))
            try {
                samples(crashed.port(path))
                val (other, otherQueue) = samples(tree.port(path))
                crashed.core.orb.orb.shutdown(false)
                crashed.core.orb.orb.destroy()
                assertEquals(2, tapConnectors("gyro0", "gyro").size, "the crashed tree's tap stays behind")

                RtcTree(TreeConfig(listOf(localisation.naming.address))).use { restarted ->
                    val queue = LinkedBlockingQueue<PortData>()
                    restarted.port(path).tap { queue += it }
                    assertTrue(queue.poll(5, TimeUnit.SECONDS) is TimedDouble)
                    assertEquals(
                        2,
                        tapConnectors("gyro0", "gyro").size,
                        "the stale tap removed, the live one kept, the new one added",
                    )
                    otherQueue.clear()
                    assertTrue(
                        otherQueue.poll(5, TimeUnit.SECONDS) is TimedDouble,
                        "the live tree's tap still receives",
                    )
                }
                other.cancel()
            } finally {
                runCatching { crashed.close() }
            }
        }

    @Test
    fun `only a data out-port can be tapped`(): Unit = runBlocking {
        val inPort = tree.port(localisation.path("laser_localise0.rtc:laser"))
        val refused = assertThrows(BadParameterException::class.java) { runBlocking { inPort.tap {} } }
        assertTrue(refused.message!!.contains("only an out-port's data can be tapped"), refused.message)
        assertFalse(inPort.connections().any { it.id.startsWith("rtcoord-tap-") })
    }

    @Test
    fun `a frozen component stays ACTIVE while its tap hears nothing, and publishes again once repaired`(): Unit =
        runBlocking {
            val laser = localisation.system.component("laser0")
            val port = tree.port(localisation.path("laser0.rtc:laser"))
            val (subscription, queue) = samples(port)
            assertTrue(queue.poll(5, TimeUnit.SECONDS) is TimedDoubleSeq)
            laser.freezeOutput()
            // Samples are stamped when written. A write under way at the freeze ends within the period after it;
            // from then on, five periods of the laser's execution publish nothing: no sample stamped among them comes.
            val frozenAt = laser.periods
            await("a period of the laser's after the freeze") { laser.periods >= frozenAt + 2 }
            val quietFrom = Instant.now()
            await("five frozen periods of the laser's") { laser.periods >= frozenAt + 7 }
            val quietTo = Instant.now()
            assertEquals(LifeCycle.ACTIVE, tree.component(localisation.path("laser0.rtc")).state())
            laser.thawOutput()
            val received = ArrayList<TimedDoubleSeq>()
            while (received.lastOrNull()?.time?.isAfter(quietTo) != true) {
                received += queue.poll(5, TimeUnit.SECONDS) as TimedDoubleSeq? ?: break
            }
            assertTrue(received.lastOrNull()?.time?.isAfter(quietTo) == true, "the laser publishes again once repaired")
            assertEquals(
                emptyList<Instant>(),
                received.map { it.time }.filter { !it.isBefore(quietFrom) && !it.isAfter(quietTo) },
                "nothing published while frozen",
            )
            subscription.cancel()
        }

    @Test
    fun `port traffic events come from the observer's SEND and RECEIVE hints, at most one per interval per port`():
        Unit = runBlocking {
        val recorder = EventRecorder()
        val options =
            EventOptions.Builder().mode(WatchMode.PUSH).trafficInterval(TRAFFIC_INTERVAL.toJavaDuration()).build()
        val laser = tree.on(localisation.path("laser0.rtc"), PortTraffic::class.java, options, recorder.handler)
        tree.on(localisation.path("laser_localise0.rtc"), PortTraffic::class.java, options, recorder.handler).use {
            val received = recorder.next<PortTraffic> { it.port == "laser" && it.source.name == "laser_localise0.rtc" }
            assertFalse(received.outgoing, "the localiser receives on its in-port laser")
            val sent = recorder.next<PortTraffic> { it.port == "laser" && it.source.name == "laser0.rtc" }
            assertTrue(sent.outgoing, "the laser sends on its out-port laser")
            laser.cancel()

            // The rate from a count: as many RECEIVE hints as make five intervals, and the time they took. The first
            // may have been on its way already, so one interval is allowed for it; at the default second between
            // hints they would take four seconds at least.
            recorder.events.clear()
            val started = TimeSource.Monotonic.markNow()
            repeat(HINTS) {
                recorder.next<PortTraffic>(timeout = 10.seconds) {
                    it.port == "laser" && it.source.name == "laser_localise0.rtc"
                }
            }
            val took = started.elapsedNow()
            assertTrue(took >= TRAFFIC_INTERVAL * (HINTS - 2), "at most one RECEIVE hint per 200 ms: $HINTS in $took")
            assertTrue(took < 1.seconds * (HINTS - 2), "the 200 ms asked for, not the default second: $HINTS in $took")
        }
    }

    /** The port's connections read now, none if the read fails; for conditions awaited outside coroutines. */
    private fun Port.runCatchingConnections(): List<Connection> = runBlocking {
        runCatching { connections() }.getOrDefault(emptyList())
    }

    private companion object {
        /** The least time between two traffic events of one port the traffic test asks for. */
        val TRAFFIC_INTERVAL = 200.milliseconds

        /** The traffic hints the traffic test counts: the first and five intervals after it. */
        const val HINTS = 6
    }
}
