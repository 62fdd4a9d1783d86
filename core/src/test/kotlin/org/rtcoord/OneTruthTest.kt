package org.rtcoord

import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.Socket
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration.Companion.milliseconds
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.assertThrows
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.EnumSource
import org.omg.CORBA.OBJ_ADAPTER
import org.omg.CORBA.ServerRequest
import org.omg.CosNaming.NamingContextExtHelper
import org.omg.CosNaming.NamingContextHelper
import org.omg.PortableServer.DynamicImplementation
import org.omg.PortableServer.POA
import org.rtcoord.FaultToleranceTest.NameServerRestart
import org.rtcoord.fixtures.awaitValue
import org.rtcoord.runtime.RuntimeOrb
import org.rtcoord.runtime.Scenarios

/**
 * The tree's model as every view sees it: snapshots that hold every event before them and followers that get every
 * event after them once, name servers that do not answer said so, components found once.
 */
class OneTruthTest {
    private val push = EventOptions(WatchMode.PUSH, heartbeat = 200.milliseconds, pollPeriod = 100.milliseconds)

    @Test
    fun `a snapshot holds every change made before it, and a follower gets each later change once`(): Unit =
        runBlocking {
            LocalisationSystem().use { localisation ->
                val tree = localisation.tree
                val gyro = tree.component(localisation.path("gyro0.rtc"))
                // A view that watched all along, as a live page's server does.
                val watching = EventRecorder()
                tree.on(localisation.host, RtcEvent::class.java, push, watching.handler)
                localisation.system.component("gyro0").deactivate()
                watching.next<StateChanged> { it.source.name == "gyro0.rtc" && it.new == LifeCycle.INACTIVE }

                val followed = EventRecorder()
                var start: SystemSnapshot? = null
                tree.follow(
                    listOf(tree.node(localisation.host)),
                    setOf(StateChanged::class.java),
                    push,
                    start = { start = it },
                    handler = followed.handler,
                )
                val snapshot = checkNotNull(start) { "follow started without a snapshot" }
                assertEquals(
                    listOf(
                        "gyro0.rtc" to LifeCycle.INACTIVE,
                        "laser0.rtc" to LifeCycle.ACTIVE,
                        "laser_localise0.rtc" to LifeCycle.ACTIVE,
                        "odometry0.rtc" to LifeCycle.ACTIVE,
                    ),
                    snapshot.components.map { it.node.name to it.state }.sortedBy { it.first },
                )
                for (entry in snapshot.components) assertEquals(
                    entry.node.state(),
                    entry.state,
                    "${entry.path} as read now",
                )

                localisation.system.component("gyro0").activate()
                val next = followed.next<StateChanged>()
                assertEquals(LifeCycle.ACTIVE, next.new)
                assertTrue(next.sequence > snapshot.sequence, "${next.sequence} after ${snapshot.sequence}")
                assertEquals(LifeCycle.ACTIVE, tree.snapshot().component(gyro)?.state)
                assertTrue(followed.drained<StateChanged>().isEmpty(), "the change is told once")
            }
        }

    @ParameterizedTest
    @EnumSource(NameServerRestart::class)
    fun `a name server stopped during a watch is reported gone and back, and nothing appears twice`(
        restart: NameServerRestart
    ): Unit = runBlocking {
        restart.start().use { server ->
            Scenarios.localisation(server.corbaloc).use { system ->
                RtcTree(TreeConfig(listOf(server.address))).use { tree ->
                    val recorder = EventRecorder()
                    val appeared = CopyOnWriteArrayList<RtcPath>()
                    tree.on("/${server.address}", RtcEvent::class.java, push) { event ->
                        if (event is NodeAppeared) appeared += event.child.path
                        recorder.handler(event)
                    }

                    server.stop()
                    assertEquals(server.address, recorder.next<NameServerLost>(timeout = 10.seconds).source.address)
                    assertFalse(tree.snapshot().nameServers.single().reachable)

                    server.restart()
                    if (!restart.keepsData) {
                        // As OpenRTM's periodic naming update does: every process registers again.
                        system.runtime.rebindAll()
                        system.master!!.runtime.bind("manager.mgr", system.master!!.ref)
                    }
                    assertTrue(recorder.next<NameServerReturned>(timeout = 10.seconds).downMillis > 0)
                    assertTrue(tree.snapshot().nameServers.single().reachable)
                    // Each created after the return: by the second's appearance every listing was read again.
                    system.runtime.create(Scenarios.relay, "late0")
                    recorder.next<NodeAppeared>(timeout = 10.seconds) { it.child.name == "late0.rtc" }
                    system.runtime.create(Scenarios.relay, "late1")
                    recorder.next<NodeAppeared>(timeout = 10.seconds) { it.child.name == "late1.rtc" }
                    val twice = appeared.groupingBy { it }.eachCount().filterValues { it > 1 }
                    assertEquals(emptyMap<RtcPath, Int>(), twice, "appeared more than once")
                }
            }
        }
    }

    @Test
    fun `a name server that answers wrongly and then not at all is reported lost once it stops answering`(): Unit =
        runBlocking {
            // As a name server being shut down does: its POA refuses the listing first, then its port is closed.
            val lists = AtomicInteger()
            RuntimeOrb.start().use { server ->
                val refusing =
                    object : DynamicImplementation() {
                        override fun invoke(request: ServerRequest) {
                            if (request.operation() == "list") lists.incrementAndGet()
                            throw OBJ_ADAPTER("shutting down")
                        }

                        override fun _all_interfaces(poa: POA?, objectId: ByteArray?): Array<String> =
                            arrayOf(NamingContextExtHelper.id(), NamingContextHelper.id())
                    }
                server.bindKey("NameService", server.activate(refusing))
                val address = "127.0.0.1:${server.port}"
                RtcTree(TreeConfig(listOf(address))).use { tree ->
                    val recorder = EventRecorder()
                    tree.on("/$address", RtcEvent::class.java, push, recorder.handler)
                    // Listed again and refused at least twice: the watch saw it answer wrongly.
                    awaitValue("two refused listings", 10.seconds) { lists.get().takeIf { it >= 2 } }
                    assertTrue(recorder.drained<NameServerLost>().isEmpty(), "a server that answers is not lost")
                    server.close()
                    assertTrue(recorder.next<NameServerLost>(timeout = 10.seconds).cause is UnreachableException)
                }
            }
        }

    @Test
    fun `a name server that never answered is reported at once, and no component is said to be missing from it`():
        Unit = runBlocking {
        // Bound and never listening: connections are refused for as long as the test holds the port.
        Socket().use { reserved ->
            reserved.bind(InetSocketAddress(InetAddress.getLoopbackAddress(), 0))
            val address = "127.0.0.1:${reserved.localPort}"
            RtcTree(TreeConfig(listOf(address))).use { tree ->
                val recorder = EventRecorder()
                tree.on("/$address", RtcEvent::class.java, push, recorder.handler)
                assertTrue(recorder.next<NameServerLost>(timeout = 5.seconds).cause is UnreachableException)
                val missing = assertThrows<RtcException> { runBlocking { tree.componentNamed("laser0") } }
                assertTrue(
                    missing is UnreachableException,
                    "not found is said only by a name server that answered: $missing",
                )
            }
        }
    }

    @Test
    fun `a component is found once, at its naming path, however many managers list it`(): Unit = runBlocking {
        LocalisationSystem().use { localisation ->
            val tree = localisation.tree
            tree.refresh()
            val components = tree.find { it is ComponentNode }.toList().map { it as ComponentNode }
            assertEquals(
                components.size,
                components.distinctBy { it.canonicalPath }.size,
                components.joinToString("\n"),
            )
            assertTrue(components.none { it.path.isAlias }, components.joinToString("\n"))
            for (component in components) assertEquals(component.path, component.canonicalPath)
            val belowManager = tree.manager(localisation.path("manager.mgr"))
            val listed =
                belowManager.children().filterIsInstance<ComponentNode>() +
                    belowManager.children().filterIsInstance<ManagerNode>().flatMap {
                        it.children().filterIsInstance<ComponentNode>()
                    }
            assertTrue(listed.isNotEmpty())
            for (alias in listed) assertTrue(
                alias.canonicalPath.startsWith(RtcPath(localisation.host)),
                "${alias.path} -> ${alias.canonicalPath}",
            )
        }
    }
}
