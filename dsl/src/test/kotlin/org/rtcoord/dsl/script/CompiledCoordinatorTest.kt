package org.rtcoord.dsl.script

import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.jar.Attributes
import java.util.jar.JarEntry
import java.util.jar.JarInputStream
import java.util.jar.JarOutputStream
import java.util.jar.Manifest
import kotlinx.coroutines.runBlocking
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertThrows
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.dsl.Coordinator
import org.rtcoord.runtime.Scenarios
import org.rtcoord.runtime.naming.NamingService

/**
 * A coordinator compiled ahead of time into a jar runs as its script does, without compiling; what is not one is
 * refused.
 */
class CompiledCoordinatorTest {
    @TempDir lateinit var directory: Path

    private val naming = NamingService.start()
    private val system = Scenarios.localisation(naming.corbaloc)
    private val config = TreeConfig(listOf(naming.address))
    private val tree = RtcTree(config)

    @AfterEach
    fun stop() {
        tree.close()
        system.close()
        naming.close()
    }

    private fun compiled(name: String, text: String): Path {
        val script = Files.writeString(directory.resolve(name), text)
        val jar = directory.resolve(name.removeSuffix(".coord.kts") + ".jar")
        runBlocking { ScriptHost(null).compile(script, jar) }
        // The jar alone: what runs cannot be the script, compiled again.
        Files.delete(script)
        return jar
    }

    @Test
    fun `a compiled coordinator runs from its jar alone, named for its script`() {
        val jar = compiled("reset.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n")
        val log = LinkedBlockingQueue<String>()
        Coordinator(tree, CompiledCoordinator.load(jar, emptyList(), config), null) { log.add(it) }
            .use { coordinator ->
                assertEquals("reset.coord.kts", coordinator.name)
                runBlocking { coordinator.start() }
                system.component("gyro0").fail()
                val fired = log.poll(20, TimeUnit.SECONDS)
                assertTrue(fired?.startsWith("rule 'gyro0.rtc enters ERROR' fired") == true, fired.toString())
            }
        assertEquals("on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n", CompiledCoordinator.source(jar))
    }

    @Test
    fun `a failure of the compiled script's body names its line`() {
        val jar = compiled("broken.coord.kts", "val limit = 3\nrequire(limit > 5) { \"limit too low: \$limit\" }\n")
        val failure = assertThrows(ScriptFailure::class.java) { CompiledCoordinator.load(jar) }
        assertEquals(listOf("broken.coord.kts:2:1: limit too low: 3"), failure.problems)
    }

    @Test
    fun `a jar compiled by another rtcoord version is refused, naming both`() {
        val jar = compiled("reset.coord.kts", "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n")
        val other =
            rewritten(jar, directory.resolve("other.jar")) { it[Attributes.Name("Rtcoord-Version")] = "0.0.1-other" }
        val failure = assertThrows(ScriptFailure::class.java) { CompiledCoordinator.load(other) }
        assertEquals(
            listOf(
                "$other: compiled by rtcoord 0.0.1-other, and this is rtcoord ${CompiledCoordinator.version}: compile it again with this one"
            ),
            failure.problems,
        )
    }

    @Test
    fun `a jar that is not a coordinator is refused with its path`() {
        val plain = directory.resolve("plain.jar")
        JarOutputStream(
                Files.newOutputStream(plain),
                Manifest().apply { mainAttributes[Attributes.Name.MANIFEST_VERSION] = "1.0" },
            )
            .use { out ->
                out.putNextEntry(JarEntry("hello.txt"))
                out.write("hello".toByteArray())
            }
        assertEquals(
            listOf(
                "$plain: not a compiled coordinator: its manifest has no Rtcoord-Coordinator (compile one with rtcoord compile)"
            ),
            assertThrows(ScriptFailure::class.java) { CompiledCoordinator.load(plain) }.problems,
        )
        val text = Files.writeString(directory.resolve("text.jar"), "not a jar at all\n")
        val refused = assertThrows(ScriptFailure::class.java) { CompiledCoordinator.load(text) }.problems.single()
        assertTrue(refused.startsWith("$text: not a compiled coordinator: not a jar"), refused)
    }

    @Test
    fun `the version a jar records is the project's, filtered in at build time`() {
        assertTrue(CompiledCoordinator.version.matches(Regex("""\d+\.\d+\.\d+.*""")), CompiledCoordinator.version)
    }

    /** [jar] copied to [to] with its manifest changed by [change]. */
    private fun rewritten(jar: Path, to: Path, change: (Attributes) -> Unit): Path {
        JarInputStream(Files.newInputStream(jar)).use { input ->
            val manifest = Manifest(input.manifest).also { change(it.mainAttributes) }
            JarOutputStream(Files.newOutputStream(to), manifest).use { out ->
                generateSequence { input.nextJarEntry }
                    .forEach { entry ->
                        out.putNextEntry(JarEntry(entry.name))
                        out.write(input.readBytes())
                        out.closeEntry()
                    }
            }
        }
        return to
    }
}
