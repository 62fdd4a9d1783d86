package org.rtcoord

import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertFalse
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.fixtures.FixtureProcess
import org.rtcoord.fixtures.await
import org.rtcoord.fixtures.awaitValue
import org.rtcoord.fixtures.runPeer

/** Every operation, checked by reading the result back through rtshell or a second tree. */
class TreeOperationsTest {
    private val localisation = LocalisationSystem()
    private val tree = localisation.tree
    private val witness = RtcTree(TreeConfig(nameServers = listOf(localisation.naming.address)))

    @AfterEach
    fun stop() {
        witness.close()
        localisation.close()
    }

    private fun path(name: String) = localisation.path(name)

    private fun rtcatState(name: String) = runPeer("rtcat", path(name)).ok().output.lines().first()

    private suspend fun seen(name: String): ComponentSnapshot =
        witness.component(path(name)).also { it.refresh() }.snapshot()

    private suspend fun seenConfiguration(name: String): ConfigurationSnapshot =
        witness.component(path(name)).also { it.refresh() }.configuration()

    @Test
    fun `activate, deactivate and reset wait for the state, as rtcat reads it`(): Unit = runBlocking {
        val laser = tree.component(path("laser0.rtc"))
        laser.deactivate()
        assertEquals("laser0.rtc  Inactive", rtcatState("laser0.rtc"))
        laser.activate()
        assertEquals("laser0.rtc  Active", rtcatState("laser0.rtc"))

        localisation.system.component("laser0").fail()
        await("laser0 in ERROR") { runBlocking { laser.state() } == LifeCycle.ERROR }
        laser.reset()
        assertEquals("laser0.rtc  Inactive", rtcatState("laser0.rtc"))
        assertEquals(LifeCycle.INACTIVE, laser.snapshots.value!!.state)
    }

    @Test
    fun `a refused transition says which state the component is in`(): Unit = runBlocking {
        val gyro = tree.component(path("gyro0.rtc"))
        val refused = assertThrows(PreconditionNotMetException::class.java) { runBlocking { gyro.activate() } }
        assertEquals(
            "${path("gyro0.rtc")}: activate refused: the component is ACTIVE in context 0, not INACTIVE",
            refused.message,
        )
        assertThrows(NotFoundException::class.java) { runBlocking { gyro.activate(ContextSelector.Handle(7)) } }
        assertThrows(NotFoundException::class.java) { runBlocking { gyro.activate(ContextSelector.Index(3)) } }
    }

    @Test
    fun `exit removes the component from the system`(): Unit = runBlocking {
        tree.component(path("odometry0.rtc")).exit()
        await("odometry0 to leave naming") {
            runBlocking { witness.refresh() }
            runBlocking { (witness.node(localisation.host) as ContextNode).children() }
                .none { it.name == "odometry0.rtc" }
        }
        assertFalse(runPeer("rtls", localisation.host + "/").ok().output.contains("odometry0.rtc"))
    }

    @Test
    fun `connect by paths makes data flow and disconnect by id stops it`(): Unit = runBlocking {
        val master = tree.manager(path("manager.mgr"))
        val localiser = master.create("odo_localise")
        assertEquals(path("odo_localise0.rtc"), localiser.path.toString())
        val odo = tree.connect(path("odometry0.rtc:odo"), path("odo_localise0.rtc:odo"))
        tree.connect(path("gyro0.rtc:gyro"), path("odo_localise0.rtc:gyro"))
        assertTrue(odo.id.isNotEmpty())

        val seenPorts = seen("odo_localise0.rtc").ports.associate { it.name to it.connectors.size }
        assertEquals(mapOf("odo" to 1, "gyro" to 1, "pose" to 0), seenPorts)
        val fixture = localisation.system.component("odo_localise0")
        awaitValue("odometry flowing into odo_localise0") { fixture.latest("odo") }

        val connections = tree.port(path("odo_localise0.rtc:odo")).connections()
        assertEquals(
            listOf(path("odometry0.rtc:odo"), path("odo_localise0.rtc:odo")),
            connections.single().ports.map { it.path.toString() },
        )

        tree.port(path("odo_localise0.rtc:odo")).disconnect(odo.id)
        assertEquals(0, seen("odo_localise0.rtc").port("odo")!!.connectors.size)
        assertEquals(
            1,
            seen("odometry0.rtc").port("odo")!!.connectors.size - 0,
            "odometry0 still feeds laser_localise0",
        )

        tree.component(path("odo_localise0.rtc")).disconnectAll()
        assertTrue(seen("odo_localise0.rtc").ports.all { it.connectors.isEmpty() })
    }

    @Test
    fun `disconnectAll passes over a connection that went since the port was read`(): Unit = runBlocking {
        val laser = tree.port(path("laser_localise0.rtc:laser"))
        assertEquals(1, laser.snapshot().connectors.size)
        // Another client removes it: the tree's read still lists it.
        witness.port(path("laser_localise0.rtc:laser")).disconnectAll()
        assertEquals(1, laser.snapshot().connectors.size)

        laser.disconnectAll()
        assertTrue(seen("laser_localise0.rtc").port("laser")!!.connectors.isEmpty())
        assertTrue(seen("laser0.rtc").port("laser")!!.connectors.isEmpty())
    }

    @Test
    fun `incompatible ports are refused before anything changes`(): Unit = runBlocking {
        val refused =
            assertThrows(BadParameterException::class.java) {
                runBlocking { tree.connect(path("gyro0.rtc:gyro"), path("laser_localise0.rtc:laser")) }
            }
        assertTrue(refused.message!!.contains("incompatible data types"), refused.message)
        assertThrows(BadParameterException::class.java) {
            runBlocking {
                tree.connect(
                    path("laser0.rtc:laser"),
                    path("laser_localise0.rtc:laser"),
                    mapOf("dataport.dataflow_type" to "pull"),
                )
            }
        }
        val missing = assertThrows(NotFoundException::class.java) { runBlocking { tree.port(path("gyro0.rtc:nope")) } }
        assertEquals("${path("gyro0.rtc")}:nope: no such port (ports: gyro)", missing.message)
        assertEquals(1, seen("laser_localise0.rtc").port("laser")!!.connectors.size)
        assertEquals(0, seen("gyro0.rtc").port("gyro")!!.connectors.size)
    }

    @Test
    fun `configuration parameters and sets change as rtconf reads them`(): Unit = runBlocking {
        val localiser = tree.component(path("laser_localise0.rtc"))
        val fixture = localisation.system.component("laser_localise0")
        localiser.setParameter("gain", "2.5")
        assertEquals("2.5", runPeer("rtconf", path("laser_localise0.rtc"), "get", "gain").ok().output.trim())
        assertEquals("+default*\n+precise", rtconfList())
        await("the component to use gain 2.5") { fixture.parameter("gain") == "2.5" }
        assertThrows(BadParameterException::class.java) {
            runBlocking { localiser.setParameter("gain", "fast", strict = true) }
        }
        assertThrows(NotFoundException::class.java) { runBlocking { localiser.setParameter("speed", "1") } }

        localiser.activateConfigurationSet("precise")
        assertEquals("+default\n+precise*", rtconfList())
        localiser.addConfigurationSet("night", mapOf("gain" to "3.0", "fail" to "0"))
        assertEquals("3.0", seenConfiguration("laser_localise0.rtc").sets.getValue("night")["gain"])
        assertEquals("precise", fixture.activeConfigurationSet, "adding a set keeps the active one")
        assertThrows(BadParameterException::class.java) { runBlocking { localiser.removeConfigurationSet("precise") } }
        localiser.removeConfigurationSet("night")
        assertFalse("night" in seenConfiguration("laser_localise0.rtc").sets)
        assertEquals("precise", fixture.activeConfigurationSet, "removing a set keeps the active one")
        val missing =
            assertThrows(NotFoundException::class.java) {
                runBlocking { localiser.activateConfigurationSet("missing") }
            }
        assertEquals(
            "${path("laser_localise0.rtc")}: no configuration set 'missing' (sets: __constraints__, default, precise)",
            missing.message,
        )
    }

    @Test
    fun `a component left with no active set is read as such and repaired by naming a set`(): Unit = runBlocking {
        val localiser = tree.component(path("laser_localise0.rtc"))
        val fixture = localisation.system.component("laser_localise0")
        // rtconf writes a set that is not active without activating anything: OpenRTM-aist then has none active.
        runPeer("rtconf", path("laser_localise0.rtc"), "-s", "precise", "set", "gain", "0.25").ok()
        val none = seenConfiguration("laser_localise0.rtc")
        assertEquals(null, none.activeSet)
        assertEquals(null, none.value("gain"))
        assertEquals("0.25", none.sets.getValue("precise")["gain"])

        val unnamed =
            assertThrows(PreconditionNotMetException::class.java) {
                runBlocking { localiser.setParameter("gain", "3.0") }
            }
        assertEquals(
            "${path("laser_localise0.rtc")}: set gain refused: no configuration set is active: name the set to change (sets: __constraints__, default, precise)",
            unnamed.message,
        )
        localiser.setParameter("gain", "0.75", set = "precise")
        assertEquals("precise", fixture.activeConfigurationSet)
        await("the component to use gain 0.75") { fixture.parameter("gain") == "0.75" }
        assertEquals("+default\n+precise*", rtconfList())

        runPeer("rtconf", path("laser_localise0.rtc"), "-s", "default", "set", "gain", "4.0").ok()
        assertEquals(null, seenConfiguration("laser_localise0.rtc").activeSet)
        localiser.activateConfigurationSet("default")
        assertEquals("default", localiser.configuration().activeSet)
        await("the component to use gain 4.0") { fixture.parameter("gain") == "4.0" }
    }

    private fun rtconfList() = runPeer("rtconf", path("laser_localise0.rtc"), "list").ok().output.trim()

    @Test
    fun `execution context rate and participants change`(): Unit = runBlocking {
        val gyro = tree.component(path("gyro0.rtc"))
        val context = gyro.executionContext()
        context.setRate(50.0)
        assertEquals(50.0, seen("gyro0.rtc").context(0)!!.rate)
        assertThrows(BadParameterException::class.java) { runBlocking { context.setRate(-1.0) } }

        val laser = tree.component(path("laser0.rtc"))
        context.add(laser)
        assertEquals(listOf(0, 1000), seen("laser0.rtc").contexts.map { it.handle })
        assertEquals(LifeCycle.INACTIVE, laser.state(ContextSelector.Handle(1000)))
        assertEquals(LifeCycle.INACTIVE, laser.state(ContextSelector.Index(1)))
        context.remove(laser)
        assertEquals(listOf(0), seen("laser0.rtc").contexts.map { it.handle })
    }

    @Test
    fun `the manager creates, deletes, loads and unloads`(): Unit = runBlocking {
        val master = tree.manager(path("manager.mgr"))
        assertTrue(master.isMaster())
        assertEquals("odo_localise0", master.create("odo_localise").snapshot().instanceName)
        assertEquals("odo_localise1", master.create("odo_localise").snapshot().instanceName)
        assertEquals("custom", master.create("odo_localise", instanceName = "custom").snapshot().instanceName)
        val unknown = assertThrows(OperationFailedException::class.java) { runBlocking { master.create("sonar") } }
        assertEquals(
            "${path("manager.mgr")}: create 'sonar' failed: nil (the manager created none; " +
                "factories: PeriodicECSharedComposite, gyro, laser, laser_localise, odo_localise, odometry; loadable modules: none)",
            unknown.message,
        )

        master.delete("odo_localise0")
        val names = (witness.node(localisation.host) as ContextNode).children().map { it.name }
        assertTrue("odo_localise0.rtc" !in names && "odo_localise1.rtc" in names, names.toString())
        assertThrows(NotFoundException::class.java) { runBlocking { master.delete("odo_localise0") } }

        val slave = master.children().filterIsInstance<ManagerNode>().single()
        slave.unloadModule("odo_localise.so")
        assertFalse(slave.factories().any { it["implementation_id"] == "odo_localise" })
        assertEquals(listOf("sensors.so", "localisers.so"), slave.loadedModules().map { it["file_path"] })
        slave.loadModule("odo_localise.so")
        assertTrue(slave.factories().any { it["implementation_id"] == "odo_localise" })
        assertThrows(BadParameterException::class.java) { runBlocking { slave.loadModule("missing.so") } }
        assertEquals(
            setOf("sensors.so", "localisers.so", "odo_localise.so"),
            slave.loadableModules().map { it["module_file_name"] }.toSet(),
        )
    }

    @Test
    fun `a manager loads the module of a type it has no factory for yet`(): Unit = runBlocking {
        val slave = tree.manager(path("manager.mgr/manager_slave"))
        assertFalse(slave.factories().any { it["implementation_id"] == "odo_localise" })
        assertEquals("odo_localise0", slave.create("odo_localise").snapshot().instanceName)
        assertTrue("odo_localise.so" in slave.loadedModules().map { it["file_path"] })
    }

    @Test
    fun `a manager that refuses is named, with its factories and loadable modules`(): Unit = runBlocking {
        localisation.system.slave!!.set_configuration("manager.modules.search_auto", "NO")
        val slave = tree.manager(path("manager.mgr/manager_slave"))
        val refused =
            assertThrows(OperationFailedException::class.java) { runBlocking { slave.create("odo_localise") } }
        assertEquals(
            "${path("manager.mgr/manager_slave")}: create 'odo_localise' failed: nil (the manager created none; " +
                "factories: PeriodicECSharedComposite, gyro, laser, laser_localise, odometry; " +
                "loadable modules: localisers.so, odo_localise.so, sensors.so)",
            refused.message,
        )
    }

    @Test
    fun `delete through the master goes to the hosting slave and returns once the name is gone`(): Unit = runBlocking {
        val master = tree.manager(path("manager.mgr"))
        val gyro = tree.component(path("gyro0.rtc"))
        val fixture = localisation.system.component("gyro0")
        master.delete("gyro0")
        assertTrue(fixture.isExited)
        // No zombie left behind: naming no longer has the name when delete returns.
        val names = (witness.node(localisation.host) as ContextNode).children().map { it.name }
        assertFalse("gyro0.rtc" in names, names.toString())
        assertFalse(
            master.children().filterIsInstance<ManagerNode>().single().children().any { it.name == "gyro0.rtc" }
        )
        assertThrows(UnreachableException::class.java) { runBlocking { gyro.refresh() } }
    }

    @Test
    fun `exit returns once the component's name has left naming`(): Unit = runBlocking {
        tree.component(path("odometry0.rtc")).exit()
        val names = (witness.node(localisation.host) as ContextNode).children().map { it.name }
        assertFalse("odometry0.rtc" in names, names.toString())
        val listed = (tree.node(localisation.host) as ContextNode).listed.value!!.map { it.name }
        assertFalse("odometry0.rtc" in listed, listed.toString())
    }

    @Test
    fun `a component re-created under its name right after it exited waits for the manager's clean-up`(): Unit =
        runBlocking {
            val master = tree.manager(path("manager.mgr"))
            localisation.system.runtime.cleanupDelay = 1.seconds
            val old = localisation.system.component("gyro0")
            // Straight to the component, as a crash or another tool would: the name lingers in the manager.
            assertEquals(RTC.ReturnCode_t.RTC_OK, old.exit())
            val again = master.create("gyro", "gyro0")
            assertEquals("gyro0", again.snapshot().instanceName)
            assertFalse(localisation.system.component("gyro0") === old)
            assertThrows(BadParameterException::class.java) { runBlocking { master.create("gyro", "gyro0") } }
        }

    @Test
    fun `exit says so when the name stays bound past the deadline`(): Unit = runBlocking {
        localisation.system.runtime.cleanupDelay = kotlin.time.Duration.INFINITE
        val stuck =
            assertThrows(TimedOutException::class.java) { runBlocking { tree.component(path("odometry0.rtc")).exit() } }
        assertTrue(stuck.message!!.contains("finalised, but is still bound in naming"), stuck.message)
    }

    @Test
    fun `a slave whose process died is left out of its master's listing, and the master creates through the others`():
        Unit = runBlocking {
        val masterAddress = localisation.system.master!!.runtime.orb.corbaloc("manager")
        FixtureProcess.start(
                "--naming",
                localisation.naming.address,
                "--scenario",
                "component:hosted0",
                "--type",
                "laser_localise",
                "--master",
                masterAddress,
            )
            .use { process ->
                val master = tree.manager(path("manager.mgr"))
                val remote = master.children().filterIsInstance<ManagerNode>().single { it.name != "manager_slave" }
                assertEquals(listOf("hosted0.rtc"), remote.children().map { it.name })

                process.kill()
                master.refresh()
                assertEquals(listOf("manager_slave"), master.children().filterIsInstance<ManagerNode>().map { it.name })
                assertEquals("hosted0", master.create("laser_localise", "hosted0").snapshot().instanceName)
            }
    }

    @Test
    fun `after a slave died, creating through the master places the component elsewhere`(): Unit = runBlocking {
        val masterAddress = localisation.system.master!!.runtime.orb.corbaloc("manager")
        val master = tree.manager(path("manager.mgr"))
        val dead =
            FixtureProcess.start(
                    "--naming",
                    localisation.naming.address,
                    "--scenario",
                    "component:hosted0",
                    "--type",
                    "gyro",
                    "--master",
                    masterAddress,
                )
                .use { process ->
                    val remote = master.children().filterIsInstance<ManagerNode>().single { it.name != "manager_slave" }
                    process.kill()
                    remote
                }
        // The slave is gone with its process; its master has the live slave load odo_localise.so.
        assertThrows(UnreachableException::class.java) { runBlocking { dead.create("odo_localise") } }
        assertEquals(path("odo_localise0.rtc"), master.create("odo_localise").path.toString())

        // No slave can create it now: the master starts one with its manager_cmd.
        localisation.system.slave!!.set_configuration("manager.modules.search_auto", "NO")
        assertThrows(OperationFailedException::class.java) { runBlocking { master.create("relay") } }
        localisation.system.startSlavesOnDemand(
            listOf(org.rtcoord.runtime.RuntimeModule("relays.so", listOf(org.rtcoord.runtime.Scenarios.relay)))
        )
        assertEquals(path("relay0.rtc"), master.create("relay").path.toString())
        assertEquals(
            listOf("relay0"),
            localisation.system.startedSlaves.single().runtime.components.map { it.instanceName },
        )
    }

    @Test
    fun `a dead registration becomes a zombie that can be unbound`(): Unit = runBlocking {
        FixtureProcess.start("--naming", localisation.naming.address, "--scenario", "component:doomed0").use { process
            ->
            assertEquals("doomed0", tree.component(path("doomed0.rtc")).snapshot().instanceName)
            process.kill()
        }
        tree.refresh()
        val zombie = (tree.node(localisation.host) as ContextNode).children().single { it.name == "doomed0.rtc" }
        assertTrue(zombie is ZombieNode, zombie.toString())
        assertTrue((zombie as ZombieNode).cause is UnreachableException, zombie.cause.toString())
        assertTrue(runPeer("rtls", localisation.host + "/").ok().output.contains("*doomed0.rtc"))

        zombie.unbind()
        assertFalse(runPeer("rtls", localisation.host + "/").ok().output.contains("doomed0.rtc"))
    }

    @Test
    fun `bad paths and wrong kinds are precise errors`(): Unit = runBlocking {
        assertThrows(BadPathException::class.java) { runBlocking { tree.node("/${localisation.naming.address}//x") } }
        assertThrows(NotFoundException::class.java) { runBlocking { tree.node(path("sonar0.rtc")) } }
        val wrong = assertThrows(WrongKindException::class.java) { runBlocking { tree.component(path("manager.mgr")) } }
        assertEquals("${path("manager.mgr")}: is a manager, not a component", wrong.message)
        assertThrows(WrongKindException::class.java) { runBlocking { tree.node(path("gyro0.rtc") + "/deeper") } }
    }
}
