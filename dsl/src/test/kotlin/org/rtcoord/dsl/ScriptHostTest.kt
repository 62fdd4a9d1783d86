package org.rtcoord.dsl

import java.nio.file.Files
import java.nio.file.Path
import java.util.jar.Attributes
import java.util.jar.JarOutputStream
import java.util.jar.Manifest
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.script.ScriptFailure
import org.rtcoord.dsl.script.ScriptHost
import org.rtcoord.profile.PortConnector
import org.rtcoord.profile.ProfileComponent
import org.rtcoord.profile.ProfileFormat
import org.rtcoord.profile.RtsProfile
import org.rtcoord.profile.RtsProfiles
import org.rtcoord.profile.TargetComponent

class ScriptHostTest {
    @TempDir lateinit var directory: Path

    private val host by lazy { ScriptHost(directory.resolve("cache")) }

    private fun script(name: String, text: String): Path =
        directory.resolve(name).also { Files.writeString(it, text.trimIndent()) }

    @Test
    fun `a script declares rules and timers, reading its arguments and the host's configuration`(): Unit = runBlocking {
        val file =
            script(
                "model.coord.kts",
                """
            nameServers("127.0.0.1:2809")
            val target = args.firstOrNull() ?: "laser0.rtc"
            on(component(target)).state(ERROR) { reset() }
            on(port("gyro0.rtc:gyro")).disconnected { log("gyro cut") }
            on(component("laser_localise0.rtc")).where { event -> event is StateChanged }.configParam("gain") { old, new -> log("${'$'}old -> ${'$'}new") }
            every(host.callTimeout) { }
            """,
            )
        val coordination =
            host.load(file, listOf("gyro0.rtc"), TreeConfig(callTimeout = kotlin.time.Duration.parse("2s")))
        assertEquals(
            listOf(
                "on gyro0.rtc enters ERROR",
                "on gyro0.rtc:gyro disconnects",
                "on laser_localise0.rtc parameter gain changes where { event -> event is StateChanged }",
                "every 2s",
            ),
            coordination.description,
        )
        assertEquals(listOf("gyro0.rtc"), coordination.args)
        assertEquals(file.fileName.toString(), coordination.name)
    }

    @Test
    fun `a script declares supervisors, and a bad one is one line naming the component and the reason`(): Unit =
        runBlocking {
            val file =
                script(
                    "supervised.coord.kts",
                    """
            val logger = component("logger0.rtc")
            supervise(component("laser0.rtc"), component("laser_localise0.rtc"), logger) {
                strategy = restForOne
                maxRestarts = 5 within 30.seconds
                backoff = exponential(1.seconds, max = 30.seconds)
                child(logger, restart = temporary)
                onEscalation { escalation -> log(escalation.reason) }
            }
            """,
                )
            assertEquals(
                listOf(
                    "supervise laser0.rtc, laser_localise0.rtc, logger0.rtc: restForOne, at most 5 within 30s, back-off exponential from 1s to 30s, permanent, logger0.rtc temporary"
                ),
                host.load(file).description,
            )
            val pattern =
                script("pattern.coord.kts", "supervise(component(\"laser0.rtc\"), component(\"*_localise0\"))")
            assertEquals(
                listOf("$pattern:1:1: cannot supervise '*_localise0': it is a pattern; name each component"),
                assertThrows(ScriptFailure::class.java) { runBlocking { host.load(pattern) } }.problems,
            )
            val stranger =
                script(
                    "stranger.coord.kts",
                    "supervise(component(\"laser0.rtc\")) { child(\"gyro0\", restart = transient) }",
                )
            assertEquals(
                listOf("$stranger:1:1: 'gyro0' is not supervised here (supervised: laser0.rtc)"),
                assertThrows(ScriptFailure::class.java) { runBlocking { host.load(stranger) } }.problems,
            )
        }

    @Test
    fun `a network's profile is read beside the script, and one that cannot be read is the machine's problem`(): Unit =
        runBlocking {
            val laser =
                ProfileComponent(
                    "RTC:AIST:sensor:laser:1.0",
                    "127.0.0.1:2809/host.host_cxt/laser0.rtc",
                    "laser0",
                    "default",
                    isRequired = true,
                )
            val localiser =
                ProfileComponent(
                    "RTC:AIST:nav:laser_localise:1.0",
                    "127.0.0.1:2809/host.host_cxt/laser_localise0.rtc",
                    "laser_localise0",
                    "precise",
                    isRequired = true,
                )
            val spare = ProfileComponent("RTC:AIST:sensor:gyro:1.0", "127.0.0.1:2809/host.host_cxt/gyro0.rtc", "gyro0")
            val connector =
                PortConnector(
                    "c1",
                    "scan",
                    TargetComponent(laser.id, "laser0", "laser0.laser"),
                    TargetComponent(localiser.id, "laser_localise0", "laser_localise0.laser"),
                    dataType = "IDL:RTC/TimedDoubleSeq:1.0",
                    interfaceType = "corba_cdr",
                    dataflowType = "push",
                )
            val profile =
                RtsProfile(
                    "RTSystem:test:nav:1.0",
                    components = listOf(laser, localiser, spare),
                    dataPortConnectors = listOf(connector),
                )
            Files.writeString(directory.resolve("nav.xml"), RtsProfiles.write(profile, ProfileFormat.XML))
            val file =
                script(
                    "nav.coord.kts",
                    "modes(\"m\") {\n    initial(\"a\")\n    mode(\"a\") { network { profile(\"nav.xml\") } }\n}\n",
                )
            val context = "/127.0.0.1:2809/host.host_cxt"
            assertEquals(
                listOf(
                    "modes m, initially a",
                    "  mode a",
                    "    network: active $context/laser0.rtc, $context/laser_localise0.rtc",
                    "    network: connected $context/laser0.rtc:laser -> $context/laser_localise0.rtc:laser",
                    "    network: configuration sets $context/laser0.rtc=default, $context/laser_localise0.rtc=precise",
                ),
                host.load(file).description,
            )
            val absent =
                script(
                    "absent.coord.kts",
                    "modes(\"m\") {\n    initial(\"a\")\n    mode(\"a\") { network { profile(\"none.xml\") } }\n}\n",
                )
            val problem =
                assertThrows(ScriptFailure::class.java) { runBlocking { host.load(absent) } }.problems.single()
            assertTrue(
                problem.startsWith("$absent:") &&
                    ": machine 'm': mode 'm/a': network: profile ${directory.resolve("none.xml")}: cannot read" in
                        problem,
                problem,
            )
        }

    @Test
    fun `compile errors come as file, line, column and message`(): Unit = runBlocking {
        val file = script("broken.coord.kts", "on(component(\"laser0.rtc\")).state(ERROR) {\n    resett()\n}\n")
        val errors = host.check(file)
        assertEquals(1, errors.size, errors.toString())
        assertTrue(errors.single().startsWith("$file:2:5: "), errors.single())
        assertTrue(errors.single().contains("resett"), errors.single())
        assertEquals(errors, assertThrows(ScriptFailure::class.java) { runBlocking { host.load(file) } }.problems)
    }

    @Test
    fun `the type errors newcomers meet first say what to write`(): Unit = runBlocking {
        val timer = script("timer.coord.kts", "every(5) { log(\"tick\") }")
        assertEquals(
            listOf(
                "$timer:1:7: Argument type mismatch: actual type is 'Int', but 'Duration' was expected (hint: a duration has a unit: write 5.seconds (or 5.milliseconds, 5.minutes))"
            ),
            host.check(timer),
        )
        val intensity = script("intensity.coord.kts", "supervise(component(\"odometry0\")) {\n    maxRestarts = 3\n}")
        assertEquals(
            listOf(
                "$intensity:2:17: Assignment type mismatch: actual type is 'Int', but 'RestartIntensity' was expected (hint: write how many restarts within how long: maxRestarts = 3 within 60.seconds)"
            ),
            host.check(intensity),
        )
    }

    @Test
    fun `a bad name in a script is its line and the reason, without Java class names`(): Unit = runBlocking {
        val file = script("port.coord.kts", "val odometry = component(\"odometry0\")\nval gyro = port(\"gyro0.rtc\")\n")
        assertEquals(
            listOf("$file:2:1: not a port: 'gyro0.rtc' (write component:port)"),
            assertThrows(ScriptFailure::class.java) { runBlocking { host.load(file) } }.problems,
        )
    }

    @Test
    fun `a script that throws while it starts names its line`(): Unit = runBlocking {
        val file = script("throws.coord.kts", "val limit = 3\nval bad = args[limit]\n")
        val failure = assertThrows(ScriptFailure::class.java) { runBlocking { host.load(file) } }
        assertTrue(
            failure.problems.single().startsWith("$file:2:1: ArrayIndexOutOfBoundsException") ||
                failure.problems.single().startsWith("$file:2:1: IndexOutOfBoundsException"),
            failure.problems.single(),
        )
    }

    @Test
    fun `an unchanged script is not compiled again, even by a new host`(): Unit = runBlocking {
        val file = script("cached.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }")
        host.load(file)
        val cached = Files.list(directory.resolve("cache")).use { it.toList() }.single()
        val compiledAt = Files.getLastModifiedTime(cached)

        ScriptHost(directory.resolve("cache")).load(file)
        assertEquals(listOf(cached), Files.list(directory.resolve("cache")).use { it.toList() })
        assertEquals(compiledAt, Files.getLastModifiedTime(cached), "the cached jar was not rewritten")

        Files.writeString(file, "on(component(\"gyro0.rtc\")).state(ERROR) { activate() }")
        host.load(file)
        assertEquals(2, Files.list(directory.resolve("cache")).use { it.count() }, "a changed script compiles anew")
    }

    @Test
    fun `a cached jar cut short is compiled again, and the cache holds whole jars only`(): Unit = runBlocking {
        val file = script("cut.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }")
        host.load(file)
        val cached = Files.list(directory.resolve("cache")).use { it.toList() }.single()
        val whole = Files.readAllBytes(cached)
        // As a process killed while writing it would leave it.
        Files.write(cached, whole.copyOf(whole.size / 2))

        ScriptHost(directory.resolve("cache")).load(file)
        assertEquals(listOf(cached), Files.list(directory.resolve("cache")).use { it.toList() }, "no part left over")
        val rewritten = Files.getLastModifiedTime(cached)
        ScriptHost(directory.resolve("cache")).load(file)
        assertEquals(rewritten, Files.getLastModifiedTime(cached), "the jar compiled again is whole: taken as it is")
    }

    @Test
    fun `a cached jar that holds no coordinator script is compiled again`(): Unit = runBlocking {
        val file =
            script(
                "foreign.coord.kts",
                "val target = args.firstOrNull() ?: \"gyro0.rtc\"\non(component(target)).state(ERROR) { reset() }",
            )
        host.load(file)
        val cached = Files.list(directory.resolve("cache")).use { it.toList() }.single()
        // Whole, but not a script: its Main-Class is not there.
        JarOutputStream(
                Files.newOutputStream(cached),
                Manifest().apply {
                    mainAttributes[Attributes.Name.MANIFEST_VERSION] = "1.0"
                    mainAttributes[Attributes.Name.MAIN_CLASS] = "Absent_coord"
                },
            )
            .close()
        assertTrue(ScriptHost(directory.resolve("cache")).isCached(file), "a whole jar is taken to be kept")

        val again = ScriptHost(directory.resolve("cache")).load(file, listOf("laser0.rtc"))
        assertEquals(listOf("on laser0.rtc enters ERROR"), again.description)
        val compiledAt = Files.getLastModifiedTime(cached)

        // From the cache, as the scripting host would have made it: arguments, name and directory alike.
        val kept = ScriptHost(directory.resolve("cache")).load(file, listOf("odometry0.rtc"))
        assertEquals(listOf("on odometry0.rtc enters ERROR"), kept.description)
        assertEquals(file.fileName.toString(), kept.name)
        assertEquals(directory.toAbsolutePath(), kept.directory)
        assertEquals(compiledAt, Files.getLastModifiedTime(cached), "the jar compiled again is kept and taken")
    }

    @Test
    fun `a missing file is one clear line`(): Unit = runBlocking {
        val missing = directory.resolve("absent.coord.kts")
        assertEquals(listOf("$missing:1:1: no such file"), host.check(missing))
    }
}
