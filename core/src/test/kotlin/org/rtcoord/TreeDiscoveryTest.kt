package org.rtcoord

import kotlin.time.Duration.Companion.seconds
import kotlin.time.measureTime
import kotlinx.coroutines.flow.toList
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.runPeer
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.rtSystem

class TreeDiscoveryTest {
    private val localisation = LocalisationSystem()
    private val tree = localisation.tree

    @AfterEach fun stop() = localisation.close()

    @Test
    fun `the tree holds what rtls -R lists`(): Unit = runBlocking {
        tree.refresh()
        // What the listings hold, a manager's aliases included, as rtls shows them (find names each component once).
        fun listed(node: Node): List<Node> =
            listOf(node) + (node as? DirectoryNode)?.listed?.value.orEmpty().flatMap(::listed)
        val ours =
            listed(tree.root)
                .filter { it !is RootNode && it !is NameServerNode }
                .map { node -> node.path.names.joinToString("/") + if (node is DirectoryNode) "/" else "" }
                .toSet()

        val listing = runPeer("rtls", "-R", "/${localisation.naming.address}/").ok().output
        assertEquals(withoutMastersCopies(rtlsPaths(listing)), ours)
    }

    /**
     * [paths] without a master's copies of its slaves' components: a master's `get_components` includes its slaves',
     * which rtls lists below both, the tree below the slave only.
     */
    private fun withoutMastersCopies(paths: Set<String>): Set<String> =
        paths
            .filterNot { path ->
                path.endsWith(".rtc") &&
                    path.substringBeforeLast('/').endsWith(".mgr") &&
                    paths.any {
                        it.startsWith(path.substringBeforeLast('/') + "/") &&
                            it.endsWith("/" + path.substringAfterLast('/')) &&
                            it != path
                    }
            }
            .toSet()

    @Test
    fun `snapshots carry service interfaces, contexts' properties and the parent, and the composition is read on demand`():
        Unit = runBlocking {
        rtSystem(localisation.naming.corbaloc) { component(Scenarios.mapServer) }
            .use {
                val node = tree.component(localisation.path("map_server0.rtc"))
                val snapshot = node.snapshot()
                assertEquals(
                    listOf(
                        PortInterface("map", "MapServer::Map", PortInterface.Polarity.PROVIDED),
                        PortInterface("pose", "Localisation::PoseSource", PortInterface.Polarity.REQUIRED),
                    ),
                    snapshot.port("map")!!.interfaces,
                )
                assertEquals(
                    mapOf(
                        "sync_transition" to "YES",
                        "transition_timeout" to "0.5",
                        "type" to "PeriodicExecutionContext",
                        "rate" to "100.0",
                    ),
                    snapshot.context(0)!!.properties,
                )
                assertEquals(null, snapshot.parent)
                assertEquals(Composition(isComposite = false, isMember = false), node.composition())
            }
    }

    @Test
    fun `components carry their profile, ports, contexts and configuration`(): Unit = runBlocking {
        val node = tree.component(localisation.path("laser_localise0.rtc"))
        val localiser = node.snapshot()
        assertEquals("laser_localise", localiser.typeName)
        assertEquals(listOf("laser", "odo", "pose"), localiser.ports.map { it.name })
        assertEquals(PortKind.DATA_IN, localiser.port("laser")!!.kind)
        assertEquals("IDL:RTC/TimedDoubleSeq:1.0", localiser.port("pose")!!.dataType)
        assertEquals(1, localiser.port("laser")!!.connectors.size)
        assertEquals(LifeCycle.ACTIVE, localiser.state)
        val context = localiser.context(0)!!
        assertTrue(context.owned && context.running)
        assertEquals("PERIODIC", context.kind)
        assertEquals(null, localiser.configuration, "configuration is read on demand")
        val configuration = node.configuration()
        assertEquals("default", configuration.activeSet)
        assertEquals("1.0", configuration.value("gain"))
        assertTrue("__constraints__" in configuration.sets)
        assertEquals(configuration, node.snapshot().configuration)
    }

    @Test
    fun `a component below its manager is the same live component as in its naming context`(): Unit = runBlocking {
        tree.refresh()
        val named = tree.component(localisation.path("laser0.rtc"))
        val managed = tree.component(localisation.path("manager.mgr/manager_slave/laser0.rtc"))
        assertTrue(named.isSameComponent(managed))
        named.deactivate()
        assertEquals(LifeCycle.INACTIVE, managed.snapshots.value!!.state)
    }

    @Test
    fun `refresh shows new bindings and drops vanished ones, keeping the nodes that stay`(): Unit = runBlocking {
        val context = tree.node(localisation.host) as ContextNode
        val before = context.children()
        val gyro = before.first { it.name == "gyro0.rtc" }

        localisation.system.runtime.create(Scenarios.relay, "newcomer0")
        localisation.system.component("odometry0").ref.exit()
        org.rtcoord.fixtures.await("odometry0 to unbind itself") {
            runBlocking { context.refresh() }
            context.listed.value!!.none { it.name == "odometry0.rtc" }
        }

        val after = context.children().map { it.name }
        assertTrue("newcomer0.rtc" in after, after.toString())
        assertTrue("odometry0.rtc" !in after, after.toString())
        assertTrue(context.children().first { it.name == "gyro0.rtc" } === gyro)
    }

    @Test
    fun `paths name servers with or without a trailing slash, and relative paths resolve`(): Unit = runBlocking {
        val server = tree.node("/${localisation.naming.address}")
        assertTrue(server is NameServerNode)
        assertTrue(tree.node("/${localisation.naming.address}/") === server)
        val working = RtcPath(localisation.host + "/")
        assertEquals("gyro0.rtc", tree.node("gyro0.rtc", working).name)
        assertEquals(NodeKind.CONTEXT, tree.node("..", RtcPath(localisation.host + "/manager.mgr")).kind)
    }

    @Test
    fun `find filters nodes across the tree`(): Unit = runBlocking {
        tree.refresh()
        val active =
            tree
                .find { it is ComponentNode && it.snapshot().state == LifeCycle.ACTIVE }
                .toList()
                .filter { it.path.names.size == 2 }
                .map { it.name }
                .toSet()
        assertEquals(setOf("laser0.rtc", "gyro0.rtc", "odometry0.rtc", "laser_localise0.rtc"), active)
        val withPose =
            tree.find { it is ComponentNode && it.snapshot().port("pose") != null }.toList().map { it.name }.toSet()
        assertEquals(setOf("laser_localise0.rtc"), withPose)

        with(NodeFilters) {
            val named =
                tree.find(predicate = name("g?ro*.rtc") and under(RtcPath(localisation.host))).toList().map {
                    it.path.toString()
                }
            assertEquals(
                listOf(localisation.path("gyro0.rtc")),
                named,
                "once, at its naming path, not again below its manager",
            )
            val laserFed =
                tree.find(predicate = hasPort("laser", "TimedDoubleSeq") and kind(NodeKind.COMPONENT)).toList()
            assertEquals(setOf("laser0.rtc", "laser_localise0.rtc"), laserFed.map { it.name }.toSet())
            assertEquals(
                4,
                tree.find(predicate = state(LifeCycle.ACTIVE)).toList().size,
                "each once, at its naming path",
            )
        }
    }

    @Test
    fun `a survey reads what listings show of every component, and a full read agrees with it`(): Unit = runBlocking {
        tree.root.survey()
        val components = tree.find { it is ComponentNode }.toList().map { it as ComponentNode }
        assertEquals(4, components.size, "each once, at its naming path")
        assertTrue(components.all { it.snapshots.value == null }, "a survey reads no snapshot")
        val laser = components.first { it.name == "laser_localise0.rtc" }.summaries.value!!
        assertEquals(mapOf(0 to LifeCycle.ACTIVE), laser.states)
        assertEquals(listOf("laser", "odo", "pose"), laser.ports.map { it.name })
        assertEquals(1, laser.ports.first { it.name == "laser" }.connectors.size)

        val surveyed = components.associateWith { it.summaries.value }
        tree.refresh()
        components.forEach { assertEquals(it.snapshots.value!!.summary, surveyed.getValue(it), it.path.toString()) }
    }

    @Test
    fun `a survey reads a component once, below its naming context and below its manager alike`(): Unit = runBlocking {
        tree.root.survey()
        for (name in listOf("laser0", "gyro0", "odometry0", "laser_localise0")) {
            assertEquals(1, localisation.system.component(name).calls("get_owned_contexts"), name)
        }
        for (inNaming in tree.find { it is ComponentNode }.toList().map { it as ComponentNode }) {
            val belowManager = tree.component(localisation.path("manager.mgr/manager_slave/${inNaming.name}"))
            assertEquals(inNaming.summaries.value, belowManager.summaries.value, inNaming.name)
        }
    }

    @Test
    fun `a survey shows a hung component as a zombie within the call deadline`(): Unit = runBlocking {
        RtcTree(TreeConfig(nameServers = listOf(localisation.naming.address), callTimeout = 1.seconds)).use { quick ->
            val gyro = localisation.system.component("gyro0")
            gyro.hang()
            try {
                val host = quick.node(localisation.host) as DirectoryNode
                val elapsed = measureTime { host.survey() }
                assertTrue(elapsed < 3.seconds, "survey took $elapsed")
                val hung = host.children().single { it.name == "gyro0.rtc" }
                assertTrue(hung is ZombieNode && hung.cause is TimedOutException, hung.toString())
                val laser = host.children().single { it.name == "laser0.rtc" } as ComponentNode
                assertEquals(LifeCycle.ACTIVE, laser.summaries.value!!.states.getValue(0))
            } finally {
                gyro.release()
            }
        }
    }

    @Test
    fun `nested contexts are listed from their name server's root, each by its whole name`(): Unit = runBlocking {
        Scenarios.scale(localisation.naming.corbaloc, 3).use {
            val sub =
                tree.node("/${localisation.naming.address}/${RuntimeProcess.hostContext}/group0.grp_cxt/sub0.sub_cxt")
                    as ContextNode
            assertEquals(listOf("relay0.rtc", "relay1.rtc", "relay2.rtc"), sub.children().map { it.name })
        }
    }

    /** Every path rtls -R prints, relative to the name server, directories with a trailing slash. */
    private fun rtlsPaths(listing: String): Set<String> {
        val paths = mutableSetOf<String>()
        var directory = ""
        for (line in listing.lines().map { it.trim() }.filter { it.isNotEmpty() }) {
            if (line.endsWith(":")) {
                directory = line.removeSuffix(":").removePrefix(".").removePrefix("/")
                continue
            }
            line.split(Regex("\\s+")).forEach { entry ->
                paths += if (directory.isEmpty()) entry else "$directory/$entry"
            }
        }
        return paths
    }
}
