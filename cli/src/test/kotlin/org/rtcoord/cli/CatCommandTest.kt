package org.rtcoord.cli

import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.rtcoord.fixtures.runPeer
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.rtSystem

/** `cat` of components, ports and managers of the localisation system. */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class CatCommandTest {
    private val localisation = Localisation()

    @AfterAll fun stop() = localisation.close()

    @Test
    fun `a component shows its profile, contexts and ports with connections as paths`() {
        val shown = runRtcoord("cat", localisation.path("laser_localise0.rtc")).ok()
        assertEquals(
            """
            laser_localise0.rtc  Active
              Instance name  laser_localise0
              Type name      laser_localise
              Version        1.0.0
              Vendor         rtcoord
              Category       fixture
              Description    rtcoord fixture component laser_localise
              Type           Monolithic
              Execution contexts
                0  PERIODIC  100.0 Hz  running  Active  owned
              Ports
                laser  DataInPort  IDL:RTC/TimedDoubleSeq:1.0
                  <- ${localisation.path("laser0.rtc:laser")}
                odo  DataInPort  IDL:RTC/TimedDoubleSeq:1.0
                  <- ${localisation.path("odometry0.rtc:odo")}
                pose  DataOutPort  IDL:RTC/TimedDoubleSeq:1.0
            
            """
                .trimIndent(),
            shown,
        )
    }

    @Test
    fun `an FSM component's state is said unknown by a tree that does not watch it, and why`() {
        rtSystem(localisation.naming.corbaloc) { component(Scenarios.microwave) }
            .use {
                val path = localisation.path("Microwave0.rtc")
                val shown = runRtcoord("cat", path).ok()
                assertTrue(
                    "  FSM state      unknown (not watched: OpenRTM-aist tells the state only to FSM4RTC observers, as it changes)\n" in
                        shown,
                    shown,
                )
                val json = runRtcoord("--json", "cat", path).ok()
                assertTrue("\"fsm\": {" in json && "\"state\": null" in json, json)
                assertTrue(
                    "FSM state" !in runRtcoord("cat", localisation.path("laser0.rtc")).ok(),
                    "a component without an FSM has no such line",
                )
            }
    }

    @Test
    fun `-l adds configuration sets, the active one marked, hidden ones left out`() {
        val shown = runRtcoord("cat", "-l", localisation.path("laser_localise0.rtc")).ok()
        assertTrue(
            shown.endsWith(
                "  Configuration\n    * default\n        fail  0\n        gain  1.0\n      precise\n        fail  0\n        gain  0.5\n"
            ),
            shown,
        )
        assertTrue("dataport.subscription_type  flush,new,periodic" in shown, shown)
        assertTrue("__constraints__" !in shown, shown)
    }

    @Test
    fun `-l shows a service port's interfaces and each context's properties, as rtcat -ll does`() {
        rtSystem(localisation.naming.corbaloc) { component(Scenarios.mapServer) }
            .use {
                val path = localisation.path("map_server0.rtc")
                val shown = runRtcoord("cat", "-l", path).ok()
                assertTrue(
                    shown.contains(
                        """
                        |    0  PERIODIC  100.0 Hz  running  Inactive  owned
                        |        rate                100.0
                        |        sync_transition     YES
                        |        transition_timeout  0.5
                        |        type                PeriodicExecutionContext
                        |  Ports
                        |    map  CorbaPort
                        |        port.port_type  CorbaPort
                        |      Provided  map   MapServer::Map
                        |      Required  pose  Localisation::PoseSource
                        |"""
                            .trimMargin()
                    ),
                    shown,
                )
                assertTrue("\n  Type           Monolithic\n" in shown, shown)
                // rtcat -ll says the same, in its own layout.
                val theirs = runPeer("rtcat", "-ll", path).ok().output
                for (line in
                    listOf(
                        "Type           Monolithic",
                        "Instance name  map",
                        "Type name      MapServer::Map",
                        "Polarity       Provided",
                        "Instance name  pose",
                        "Type name      Localisation::PoseSource",
                        "Polarity       Required",
                        "sync_transition     YES",
                        "transition_timeout  0.5",
                        "type                PeriodicExecutionContext",
                        "rate                100.0",
                    )) assertTrue(line in theirs, "rtcat -ll lacks `$line`:\n$theirs")
            }
    }

    @Test
    fun `--json holds the interfaces, the contexts' properties, the parent and the type`() {
        rtSystem(localisation.naming.corbaloc) { component(Scenarios.mapServer) }
            .use {
                val json = runRtcoord("--json", "cat", localisation.path("map_server0.rtc")).ok()
                assertTrue("\"parent\": null,\n    \"type\": \"Monolithic\"," in json, json)
                assertTrue(
                    "\"properties\": {\n          \"rate\": \"100.0\",\n          \"sync_transition\": \"YES\"," in
                        json,
                    json,
                )
                val interfaces =
                    """
                    "interfaces": [
                      {
                        "instanceName": "map",
                        "typeName": "MapServer::Map",
                        "polarity": "PROVIDED"
                      },
                      {
                        "instanceName": "pose",
                        "typeName": "Localisation::PoseSource",
                        "polarity": "REQUIRED"
                      }
                    ],
                    """
                        .trimIndent()
                        .prependIndent("        ")
                assertTrue(interfaces in json, json)
            }
    }

    @Test
    fun `a port path shows that port only`() {
        val shown = runRtcoord("cat", localisation.path("laser0.rtc:laser")).ok()
        assertEquals(
            "laser  DataOutPort  IDL:RTC/TimedDoubleSeq:1.0\n  -> ${localisation.path("laser_localise0.rtc:laser")}\n",
            shown,
        )
    }

    @Test
    fun `a manager shows its profile, modules and factories`() {
        val shown = runRtcoord("cat", localisation.path("manager.mgr/manager_slave")).ok()
        assertTrue(shown.startsWith("manager_slave  slave\n  Profile\n"), shown)
        assertTrue("  Loaded modules\n    sensors.so\n    localisers.so\n  Loadable modules\n" in shown, shown)
        assertTrue(
            Regex("""\n {4}laser_localise +rtcoord fixture component laser_localise\n""").containsMatchIn(shown),
            shown,
        )
    }

    @Test
    fun `--json holds the same report`() {
        val json = runRtcoord("--json", "cat", localisation.path("gyro0.rtc")).ok()
        assertTrue(
            json.startsWith(
                "[\n  {\n    \"path\": \"${localisation.path("gyro0.rtc")}\",\n    \"kind\": \"component\","
            ),
            json,
        )
        assertTrue("\"state\": \"ACTIVE\"" in json && "\"dataType\": \"IDL:RTC/TimedDouble:1.0\"" in json, json)
    }

    @Test
    fun `a bad port names the ports there are`() {
        val line = runRtcoord("cat", localisation.path("gyro0.rtc:sonar")).failure()
        assertEquals("rtcoord: ${localisation.path("gyro0.rtc:sonar")}: no such port (ports: gyro)", line)
    }
}
