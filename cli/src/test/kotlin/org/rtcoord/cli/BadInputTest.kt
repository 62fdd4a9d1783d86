package org.rtcoord.cli

import java.nio.file.Files
import java.nio.file.Path
import org.junit.jupiter.api.AfterAll
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.TestInstance
import org.junit.jupiter.params.ParameterizedTest
import org.junit.jupiter.params.provider.MethodSource
import org.rtcoord.runtime.Behaviour
import org.rtcoord.runtime.ComponentContext
import org.rtcoord.runtime.ComponentType
import org.rtcoord.runtime.RuntimeProcess
import org.rtcoord.runtime.Scenarios

/**
 * Bad input, command by command and kind by kind: exit status 1, nothing on stdout, one exact `rtcoord: <what>: <why>`
 * line on stderr, and the live system as it was (components, states, connections, configuration, loaded modules, read
 * back from the components themselves). Where a command of several steps fails midway, the line says what was done and
 * what was not.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class BadInputTest {
    private val localisation = Localisation()
    private val ns = localisation.naming.address
    private val host = localisation.host
    private val laser = localisation.path("laser0.rtc:laser")
    private val localiser = localisation.path("laser_localise0.rtc")
    private val manager = localisation.path("manager.mgr")
    private val scripts: Path = Files.createTempDirectory("bad-input")

    /** Two different components named twin0, in two contexts, for the ambiguous name. */
    private val twins =
        RuntimeProcess.start(localisation.naming.corbaloc, listOf("right.host_cxt")).also {
            it.create(Scenarios.relay, "twin0")
            localisation.system.runtime.create(Scenarios.relay, "twin0", contexts = listOf("left.host_cxt"))
        }

    @AfterAll
    fun stop() {
        twins.close()
        localisation.close()
        scripts.toFile().deleteRecursively()
    }

    // The commands and their path arguments: every command meets an unknown path, a path of the wrong
    // kind and an unreachable name server.

    /** A command, how it takes a path, and a path of the wrong kind for it with the reason it gives. */
    class Case(
        private val name: String,
        val arguments: (path: String) -> List<String>,
        val wrongKind: (Localisation) -> Pair<String, String>,
    ) {
        override fun toString() = name
    }

    fun cases(): List<Case> {
        val notComponent = { l: Localisation -> l.path("manager.mgr") to "is a manager, not a component" }
        val port = { l: Localisation ->
            l.path("laser0.rtc:laser") to "is a port, not a component, manager or directory"
        }
        return listOf(
            Case("ls", { listOf("ls", it) }, { it.path("laser0.rtc") + "/" to "is a component, not a directory" }),
            Case("cat", { listOf("cat", it) }, { it.host to "is a context, not a component, port or manager" }),
            Case("find", { listOf("find", it) }, port),
            Case("act", { listOf("act", it) }, notComponent),
            Case("deact", { listOf("deact", it) }, notComponent),
            Case("reset", { listOf("reset", it) }, notComponent),
            Case("exit", { listOf("exit", it) }, notComponent),
            // A port's errors name its component.
            Case(
                "con",
                { listOf("con", "$it:laser", "${it.substringBeforeLast('/')}/laser_localise0.rtc:laser") },
                notComponent,
            ),
            Case("dis", { listOf("dis", "$it:laser") }, notComponent),
            Case("conf", { listOf("conf", it) }, notComponent),
            Case("mgr", { listOf("mgr", it, "list") }, { it.path("laser0.rtc") to "is a component, not a manager" }),
            Case("del", { listOf("del", it) }, { it.path("laser0.rtc") to "is a live component, not a zombie" }),
            Case("watch", { listOf("watch", it, "--for", "1s") }, port),
            Case("graph", { listOf("graph", it) }, port),
        )
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    fun `an unknown path is not found`(case: Case) {
        val unknown = localisation.path("sonar0.rtc")
        val line = runRtcoord(*case.arguments(unknown).toTypedArray()).failure()
        assertEquals("rtcoord: $unknown: not found", line)
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    fun `a path of the wrong kind says what it is`(case: Case) {
        val (path, reason) = case.wrongKind(localisation)
        val line = runRtcoord(*case.arguments(path).toTypedArray()).failure()
        assertEquals("rtcoord: ${path.removeSuffix("/")}: $reason", line)
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    fun `an unreachable name server fails fast and says so`(case: Case) {
        val dead = deadNameServer()
        val started = System.nanoTime()
        val line =
            runRtcoord(*case.arguments("/$dead/${localisation.host.substringAfterLast('/')}/laser0.rtc").toTypedArray())
                .failure()
        assertTrue(line.startsWith("rtcoord: /$dead: unreachable ("), line)
        assertTrue(System.nanoTime() - started < 2_000_000_000L, "took ${(System.nanoTime() - started) / 1_000_000} ms")
    }

    // The kinds of bad input, each with its exact error.

    /** One kind of bad input: the command line, and the one error line it must give. */
    class Row(private val name: String, val arguments: List<String>, val error: String) {
        override fun toString() = name
    }

    private fun script(name: String, text: String): String =
        scripts.resolve(name).also { Files.writeString(it, text) }.toString()

    private fun run(script: String) = listOf("-n", ns, "run", "--for", "1s", script)

    fun rows(): List<Row> {
        val syntax = script("syntax.coord.kts", "on(component(\"laser0\")).state(ERROR) {\n    reset()\n")
        val type = script("type.coord.kts", "on(component(\"laser0\")).state(\"ERROR\") { reset() }\n")
        val unresolved = script("unresolved.coord.kts", "on(component(\"laser0\")).state(ERROR) {\n    resett()\n}\n")
        val throwing =
            script(
                "throwing.coord.kts",
                "on(component(\"laser0\")).state(ERROR) { reset() }\nerror(\"no map loaded\")\n",
            )
        val unknown = script("unknown.coord.kts", "on(component(\"sonar0\")).state(ERROR) { reset() }\n")
        val ambiguous = script("ambiguous.coord.kts", "on(component(\"twin0\")).state(ERROR) { reset() }\n")
        val wrongKind =
            script("wrong-kind.coord.kts", "on(manager(\"${localisation.path("laser0.rtc")}\")).created { }\n")
        val noManager = script("no-manager.coord.kts", "on(manager(\"sonar.mgr\")).created { }\n")
        val gyro = localisation.path("gyro0.rtc:gyro")
        val odometry = localisation.path("odometry0.rtc:odo")
        val connector =
            localisation.system
                .component("laser0")
                .ref
                .get_ports()
                .single()
                .get_connector_profiles()
                .single()
                .connector_id
        return listOf(
            // Malformed paths.
            Row(
                "empty segment",
                listOf("cat", "$host//laser0.rtc"),
                "rtcoord: $host//laser0.rtc: bad path: empty segment (segment 3)",
            ),
            Row(
                "port number out of range",
                listOf("ls", "/127.0.0.1:99999/"),
                "rtcoord: /127.0.0.1:99999/: bad path: bad port '99999' (segment 1)",
            ),
            Row(
                "empty port name",
                listOf("con", localisation.path("laser0.rtc:"), "$localiser:laser"),
                "rtcoord: ${localisation.path("laser0.rtc:")}: bad path: empty port name (segment 3)",
            ),
            Row(
                "relative path without a working directory",
                listOf("deact", "laser0.rtc"),
                "rtcoord: laser0.rtc: a relative path needs a start: give -n HOST[:PORT] (relative paths start at the first name server) or set RTCOORD_CWD",
            ),
            // Unknown names.
            Row(
                "unknown component among several",
                listOf("deact", localisation.path("laser0.rtc"), localisation.path("sonar0.rtc")),
                "rtcoord: ${localisation.path("sonar0.rtc")}: not found",
            ),
            Row(
                "unknown port",
                listOf("con", localisation.path("laser0.rtc:sonar"), "$localiser:laser"),
                "rtcoord: ${localisation.path("laser0.rtc:sonar")}: no such port (ports: laser)",
            ),
            // Names close to one that exists.
            Row(
                "a mistyped component",
                listOf("act", localisation.path("lasr0.rtc")),
                "rtcoord: ${localisation.path("lasr0.rtc")}: not found; did you mean laser0.rtc?",
            ),
            Row(
                "a component without its kind",
                listOf("cat", localisation.path("gyro0")),
                "rtcoord: ${localisation.path("gyro0")}: not found; did you mean gyro0.rtc?",
            ),
            Row(
                "a mistyped port",
                listOf("con", localisation.path("laser0.rtc:lasr"), "$localiser:laser"),
                "rtcoord: ${localisation.path("laser0.rtc:lasr")}: no such port (ports: laser); did you mean laser?",
            ),
            Row(
                "a mistyped context",
                listOf("ls", "/$ns/${RuntimeProcess.hostContext.replace(".host_cxt", ".hst_cxt")}/"),
                "rtcoord: /$ns/${RuntimeProcess.hostContext.replace(".host_cxt", ".hst_cxt")}: not found; did you mean ${RuntimeProcess.hostContext}?",
            ),
            Row(
                "unknown connector",
                listOf("dis", laser, "--id", "nope"),
                "rtcoord: $laser: no connector 'nope' (connectors: $connector)",
            ),
            Row(
                "unknown parameter",
                listOf("conf", localiser, "set", "nope", "1"),
                "rtcoord: $localiser: no parameter 'nope' in configuration set 'default' (parameters: fail, gain)",
            ),
            Row(
                "unknown component of a manager",
                listOf("mgr", manager, "delete", "sonar0"),
                "rtcoord: $manager: no component 'sonar0' is hosted by this manager or its slaves",
            ),
            Row(
                "unknown component in a script",
                run(unknown),
                "rtcoord: $unknown:1:14: sonar0: no such component on $ns",
            ),
            Row(
                "unknown manager in a script",
                run(noManager),
                "rtcoord: $noManager:1:12: sonar.mgr: no such manager on $ns",
            ),
            // Ambiguous names.
            Row(
                "ambiguous component in a script",
                run(ambiguous),
                "rtcoord: $ambiguous:1:14: twin0: ambiguous: matches /$ns/left.host_cxt/twin0.rtc, /$ns/right.host_cxt/twin0.rtc",
            ),
            // Wrong node kinds.
            Row("a context for a component", listOf("act", host), "rtcoord: $host: is a context, not a component"),
            Row(
                "a component for a port",
                listOf("con", localisation.path("laser0.rtc"), "$localiser:laser"),
                "rtcoord: ${localisation.path("laser0.rtc")}: bad path: no port given (component.rtc:port) (segment 3)",
            ),
            Row(
                "a component for a manager in a script",
                run(wrongKind),
                "rtcoord: $wrongKind:1:12: ${localisation.path("laser0.rtc")}: is a component, not a manager",
            ),
            // Invalid connector properties.
            Row(
                "a dataflow type the port does not offer",
                listOf("con", laser, "$localiser:laser", "--allow-duplicate", "-p", "dataport.dataflow_type=telepathy"),
                "rtcoord: $laser: connect rejected: $laser does not offer dataport.dataflow_type=telepathy (offers push)",
            ),
            Row(
                "an interface type the port does not offer",
                listOf("con", laser, "$localiser:laser", "--allow-duplicate", "-p", "dataport.interface_type=shm"),
                "rtcoord: $laser: connect rejected: $laser does not offer dataport.interface_type=shm (offers corba_cdr)",
            ),
            // Incompatible ports.
            Row(
                "different data types",
                listOf("con", gyro, "$localiser:laser"),
                "rtcoord: $gyro: connect rejected: incompatible data types: $gyro carries IDL:RTC/TimedDouble:1.0, $localiser:laser carries IDL:RTC/TimedDoubleSeq:1.0",
            ),
            Row(
                "two out-ports",
                listOf("con", laser, odometry),
                "rtcoord: $laser: connect rejected: a data connection needs an out-port and an in-port",
            ),
            Row(
                "a port to itself",
                listOf("con", laser, laser),
                "rtcoord: $laser: connect rejected: $laser is given twice: a port cannot connect to itself",
            ),
            // Invalid configuration values.
            Row(
                "a value of the wrong type for the declared constraint, --strict",
                listOf("conf", localiser, "set", "--strict", "gain", "abc"),
                "rtcoord: $localiser: set gain rejected: 'abc' is not a number (constraint 0<x<10)",
            ),
            Row(
                "a value outside the declared constraint, --strict",
                listOf("conf", localiser, "set", "--strict", "gain", "42"),
                "rtcoord: $localiser: set gain rejected: '42' is outside 0<x<10",
            ),
            // Unknown configuration sets.
            Row(
                "set in an unknown set",
                listOf("conf", localiser, "set", "gain", "2", "--set", "nosuch"),
                "rtcoord: $localiser: no configuration set 'nosuch' (sets: __constraints__, default, precise)",
            ),
            Row(
                "activate an unknown set",
                listOf("conf", localiser, "act", "nosuch"),
                "rtcoord: $localiser: no configuration set 'nosuch' (sets: __constraints__, default, precise)",
            ),
            Row(
                "get from an unknown set",
                listOf("conf", localiser, "get", "gain", "--set", "nosuch"),
                "rtcoord: $localiser: no configuration set 'nosuch' (sets: __constraints__, default, precise)",
            ),
            // Managers: types, names and modules that do not exist.
            Row(
                "a component type no factory makes",
                listOf("mgr", manager, "create", "sonar"),
                "rtcoord: $manager: create 'sonar' failed: nil (the manager created none; " +
                    "factories: PeriodicECSharedComposite, gyro, laser, laser_localise, odometry; loadable modules: none)",
            ),
            Row(
                "an instance name in use",
                listOf("mgr", manager, "create", "laser", "--name", "laser0"),
                "rtcoord: $manager: create 'laser' rejected: a component named 'laser0' exists already",
            ),
            Row(
                "a module that is not there",
                listOf("mgr", manager, "load", "nosuch.so"),
                "rtcoord: $manager: load module 'nosuch.so' rejected: BAD_PARAMETER (loadable: none)",
            ),
            Row(
                "a module that is not loaded",
                listOf("mgr", manager, "unload", "nosuch.so"),
                "rtcoord: $manager: unload module 'nosuch.so' rejected: BAD_PARAMETER (loaded: localisers.so, sensors.so)",
            ),
            // Scripts.
            Row("a script with a syntax error", run(syntax), "rtcoord: $syntax:2:12: Syntax error: Expecting '}'."),
            Row(
                "a script with a type error",
                run(type),
                "rtcoord: $type:1:31: Argument type mismatch: actual type is 'String', but 'LifeCycle' was expected.",
            ),
            Row(
                "a script calling what does not exist",
                run(unresolved),
                "rtcoord: $unresolved:2:5: Unresolved reference 'resett'.",
            ),
            Row("a script that throws at start", run(throwing), "rtcoord: $throwing:2:1: no map loaded"),
        )
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("rows")
    fun `bad input gets one exact line and changes nothing`(row: Row) {
        val before = liveState()
        assertEquals(row.error, runRtcoord(*row.arguments.toTypedArray()).failure())
        assertEquals(before, liveState(), "the live system after the error")
    }

    // Several steps, one failing midway: the error says what was done and what was not, and it is so.

    @Test
    fun `a lifecycle change of several components that fails midway says which were changed and which not`() {
        val stubborn =
            ComponentType(
                "stubborn",
                behaviour = {
                    object : Behaviour {
                        override fun onActivated(rtc: ComponentContext) = false
                    }
                },
            )
        localisation.system.runtime.create(stubborn, "stubborn0")
        try {
            val (gyro, odometry, refusing) =
                listOf("gyro0.rtc", "odometry0.rtc", "stubborn0.rtc").map(localisation::path)
            runRtcoord("deact", gyro, odometry).ok()
            val line = runRtcoord("act", gyro, refusing, odometry).failure()
            assertEquals(
                "rtcoord: $refusing: activate failed: RTC_ERROR (the component went to ERROR in context 0); activated: $gyro; not attempted: $odometry",
                line,
            )
            val states = listOf("gyro0", "stubborn0", "odometry0").map { localisation.system.component(it).state }
            assertEquals(
                listOf(
                    RTC.LifeCycleState.ACTIVE_STATE,
                    RTC.LifeCycleState.ERROR_STATE,
                    RTC.LifeCycleState.INACTIVE_STATE,
                ),
                states,
            )
        } finally {
            localisation.system.component("stubborn0").exit()
            runRtcoord("act", localisation.path("odometry0.rtc")).ok()
        }
    }

    @Test
    fun `a handler that creates a component and then fails to connect it logs what it did, and connects nothing`() {
        val handler =
            script(
                "create-then-connect.coord.kts",
                "after(0.seconds) {\n    val localiser = manager().create(\"odo_localise\")\n    connect(\"gyro0.rtc:gyro\", localiser.port(\"odo\"))\n}\n",
            )
        val before = liveState()
        try {
            val log =
                runRtcoordUntil("-n", ns, "run", handler, what = "the handler's failure") {
                        "failed at create-then-connect.coord.kts:3: " in it
                    }
                    .ok()
                    .lines()
            val created = log.single { "created " in it }.substringAfter("created ")
            // The first: the summary repeats it.
            val failure = log.first { "timer after 0s failed at create-then-connect.coord.kts:3: " in it }
            assertTrue(
                failure.endsWith(
                    "${localisation.path("gyro0.rtc:gyro")}: connect rejected: incompatible data types: " +
                        "${localisation.path("gyro0.rtc:gyro")} carries IDL:RTC/TimedDouble:1.0, $created:odo carries IDL:RTC/TimedDoubleSeq:1.0"
                ),
                log.joinToString("\n"),
            )
            val after = liveState()
            // The manager loaded the module the created component's type is in, as OpenRTM-aist's does.
            assertEquals(
                before + ("modules" to "[localisers.so, odo_localise.so, sensors.so]"),
                after - "odo_localise0",
                "nothing but the created component changed",
            )
            assertTrue(
                after.getValue("odo_localise0").contains("odo=[]"),
                "the created component is not connected: ${after["odo_localise0"]}",
            )
        } finally {
            // Left as found for the other tests: the component gone, its module unloaded.
            localisation.system.runtime.components.firstOrNull { it.instanceName == "odo_localise0" }?.exit()
            localisation.system.slave!!.ref.unload_module("odo_localise.so")
        }
    }

    @Test
    fun `run --fail-on-handler-error stops at the first failed handler with status 1, a plain run keeps going`() {
        val failing = script("failing.coord.kts", "every(200.milliseconds) { error(\"the handler gives up\") }\n")
        val stopped = runRtcoord("-n", ns, "run", "--for", "20s", "--fail-on-handler-error", failing)
        assertEquals(1, stopped.statusCode, stopped.output)
        assertTrue(
            stopped.output.contains(
                "timer every 200ms failed at failing.coord.kts:1: IllegalStateException: the handler gives up"
            ),
            stopped.output,
        )
        assertTrue(
            stopped.output.contains("stopped by a handler that failed (--fail-on-handler-error); 1 handler failure;"),
            stopped.output,
        )

        val kept =
            RunningCommand("-n", ns, "run", failing).use { running ->
                running.awaitLines("a second failure", 2) { "timer every 200ms failed at failing.coord.kts:1" in it }
                running.stop().ok()
            }
        assertTrue(Regex("stopped by SIGINT; [2-9]\\d* handler failures").containsMatchIn(kept), kept)
    }

    @Test
    fun `a script configuring several parameters changes none when one of them is bad`() {
        val configure =
            script(
                "configure.coord.kts",
                "after(0.seconds) {\n    component(\"laser_localise0\").configure {\n        set(\"gain\", \"2.0\")\n        set(\"nope\", \"1\")\n    }\n}\n",
            )
        val before = liveState()
        val log =
            runRtcoordUntil("-n", ns, "run", configure, what = "the handler's failure") {
                    "failed at configure.coord.kts:2: " in it
                }
                .ok()
        assertTrue(
            log.lines().any {
                it.endsWith(
                    "timer after 0s failed at configure.coord.kts:2: NotFoundException: $localiser: no parameter 'nope' in configuration set 'default' (parameters: fail, gain)"
                )
            },
            log,
        )
        assertEquals(before, liveState())
    }

    /**
     * Everything bad input could change, read from the live objects: each component's state, its ports' connectors, its
     * configuration sets and active set; the slave manager's loaded modules.
     */
    private fun liveState(): Map<String, String> {
        // An exited component stays listed until its manager's clean-up; it is no longer part of the system.
        val components =
            localisation.system.runtime.components
                .filterNot { it.isExited }
                .associate { component ->
                    val ports =
                        component.ref
                            .get_ports()
                            .map { port ->
                                port.get_port_profile().name.substringAfter('.') +
                                    "=" +
                                    port.get_connector_profiles().map { it.connector_id }.sorted()
                            }
                            .sorted()
                    val configuration = component.ref.get_configuration()
                    val sets =
                        configuration
                            .get_configuration_sets()
                            .associate { set ->
                                set.id to
                                    set.configuration_data
                                        .associate { it.name to it.value.extract_string() }
                                        .toSortedMap()
                            }
                            .toSortedMap()
                    component.instanceName to
                        "${component.state.value()} $ports active=${configuration.get_active_configuration_set().id} $sets"
                }
        val modules =
            localisation.system.slave!!.ref.get_loaded_modules().map { module ->
                module.properties.joinToString { it.value.extract_string() }
            }
        return components + ("modules" to modules.sorted().toString())
    }
}
