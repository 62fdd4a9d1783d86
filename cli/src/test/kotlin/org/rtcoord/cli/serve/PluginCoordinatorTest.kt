package org.rtcoord.cli.serve

import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.nio.file.Files
import java.nio.file.Path
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.int
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.junit.jupiter.api.fail
import org.junit.jupiter.api.io.TempDir
import org.rtcoord.cli.Localisation

/**
 * What the README tells an Eclipse plug-in to do to run a coordinator, which the bundle cannot (the dsl needs the
 * Kotlin compiler): start `rtcoord run SCRIPT --serve --serve-port 0` as a process, read the address it serves on from
 * its output, follow the coordinator through the live view's API with `java.net.http`, and stop it with SIGTERM
 * (`Process.destroy`).
 */
class PluginCoordinatorTest {
    private val localisation = Localisation()
    private val http = HttpClient.newHttpClient()
    private var process: Process? = null

    @AfterEach
    fun stop() {
        process?.destroyForcibly()
        localisation.close()
    }

    @Test
    fun `a plug-in runs a coordinator as a process and reads its rules through the API`(@TempDir directory: Path) {
        val script =
            directory.resolve("reset.coord.kts").also {
                Files.writeString(it, "on(component(\"gyro0.rtc\")).state(ERROR) { reset() }\n")
            }
        val java = Path.of(System.getProperty("java.home"), "bin", "java").toString()
        val started =
            ProcessBuilder(
                    java,
                    "-cp",
                    System.getProperty("java.class.path"),
                    "org.rtcoord.cli.MainKt",
                    "-n",
                    localisation.naming.address,
                    "run",
                    script.toString(),
                    "--serve",
                    "--serve-port",
                    "0",
                )
                .redirectErrorStream(true)
                .start()
                .also { process = it }
        val lines = LinkedBlockingQueue<String>()
        Thread { started.inputStream.bufferedReader().forEachLine { lines += it } }.apply { isDaemon = true }.start()

        var url: String? = null
        while (url == null) {
            val line = lines.poll(120, TimeUnit.SECONDS) ?: fail("run --serve printed no address")
            url = Regex("serving .* on (http://\\S+)").find(line)?.groupValues?.get(1)
        }
        val base = url.substringBefore('?').removeSuffix("/")

        // The event stream: a snapshot (the coordinator's state inside it), then a `coordinator` event at each change.
        val stream = LinkedBlockingQueue<String>()
        http
            .sendAsync(HttpRequest.newBuilder(URI("$base/api/events")).build(), HttpResponse.BodyHandlers.ofLines())
            .thenAccept { response -> response.body().forEach { stream += it } }
        localisation.system.component("gyro0").fail()
        var firings = 0
        var event = ""
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30)
        while (firings == 0) {
            val line =
                stream.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS)
                    ?: fail("no firing of the rule on the event stream")
            when {
                line.startsWith("event: ") -> event = line.removePrefix("event: ")
                line.startsWith("data: ") && (event == "snapshot" || event == "coordinator") -> {
                    val data = Json.parseToJsonElement(line.removePrefix("data: ")).jsonObject
                    val coordinator = if (event == "snapshot") data["coordinator"]?.jsonObject else data
                    val rule =
                        coordinator
                            ?.get("rules")
                            ?.jsonArray
                            ?.map { it.jsonObject }
                            ?.single { it["description"]?.jsonPrimitive?.content == "gyro0.rtc enters ERROR" }
                    firings = rule?.get("firings")?.jsonPrimitive?.int ?: 0
                }
            }
        }
        assertEquals(1, firings, "the rule's firings as the API showed them")

        started.destroy()
        assertTrue(started.waitFor(60, TimeUnit.SECONDS), "run did not end after SIGTERM")
        assertEquals(0, started.exitValue())
        assertEquals(emptySet<String>(), localisation.system.component("gyro0").observerIds)
    }
}
