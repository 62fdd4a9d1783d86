package org.rtcoord.cli.serve

import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.net.http.WebSocket
import java.nio.file.Files
import java.nio.file.Path
import java.util.Base64
import java.util.concurrent.CompletableFuture
import java.util.concurrent.CompletionStage
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlin.time.Duration
import kotlin.time.Duration.Companion.seconds
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.buildJsonObject
import kotlinx.serialization.json.int
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import kotlinx.serialization.json.put
import org.junit.jupiter.api.Assertions.fail
import org.junit.jupiter.api.Assumptions.assumeTrue
import org.rtcoord.fixtures.awaitValue

/**
 * Chromium (found as [Chromium] finds it), headless, driven over the Chrome DevTools Protocol on one page: navigate,
 * evaluate JavaScript, take screenshots. Its DevTools port is chosen by Chromium and listens on loopback. Missing
 * Chromium skips the test outside CI and fails it in CI, as missing peers do.
 */
class HeadlessChromium
private constructor(
    private val process: Process,
    private val profile: Path,
    private val socket: WebSocket,
    private val replies: Replies,
) : AutoCloseable {
    private val ids = AtomicInteger()

    /** Answers to commands by id, put together from the socket's text frames. */
    private class Replies : WebSocket.Listener {
        val pending = ConcurrentHashMap<Int, CompletableFuture<JsonObject>>()
        private val text = StringBuilder()

        override fun onText(socket: WebSocket, data: CharSequence, last: Boolean): CompletionStage<*>? {
            text.append(data)
            if (last) {
                val message = Json.parseToJsonElement(text.toString()).jsonObject
                text.setLength(0)
                message["id"]?.jsonPrimitive?.int?.let { pending.remove(it)?.complete(message) }
            }
            socket.request(1)
            return null
        }
    }

    /** Sends [method] with [params] and returns its result; fails on a protocol error. */
    fun send(method: String, params: JsonObject = JsonObject(emptyMap()), timeout: Duration = 60.seconds): JsonObject {
        val id = ids.incrementAndGet()
        val reply = CompletableFuture<JsonObject>()
        replies.pending[id] = reply
        socket
            .sendText(
                buildJsonObject {
                    put("id", id)
                    put("method", method)
                    put("params", params)
                }
                    .toString(),
                true,
            )
            .join()
        val message = reply.get(timeout.inWholeMilliseconds, TimeUnit.MILLISECONDS)
        message["error"]?.let { fail<Unit>("$method: $it") }
        return message["result"]!!.jsonObject
    }

    /** Opens [url] in the page. */
    fun navigate(url: String) {
        send("Page.navigate", buildJsonObject { put("url", url) })
    }

    /** The value of [expression] (awaited when it is a promise), as JSON. */
    fun evaluate(expression: String): JsonElement {
        val result =
            send(
                "Runtime.evaluate",
                buildJsonObject {
                    put("expression", expression)
                    put("returnByValue", true)
                    put("awaitPromise", true)
                },
            )
        result["exceptionDetails"]?.let { fail<Unit>("$expression: $it") }
        return result["result"]!!.jsonObject["value"] ?: JsonObject(emptyMap())
    }

    /**
     * Waits until [expression] is true in the page, failing after [timeout] with [what]. It may throw meanwhile (the
     * page is still loading): that counts as false.
     */
    fun await(what: String, timeout: Duration = 60.seconds, expression: String) {
        awaitValue(what, timeout) {
            evaluate("(() => { try { return Boolean($expression); } catch (e) { return false; } })()")
                .jsonPrimitive
                .content
                .toBooleanStrict()
                .takeIf { it }
        }
    }

    /** Saves a PNG of the page to [file]. */
    fun screenshot(file: Path) {
        val data =
            send("Page.captureScreenshot", buildJsonObject { put("format", "png") })["data"]!!.jsonPrimitive.content
        Files.createDirectories(file.parent)
        Files.write(file, Base64.getDecoder().decode(data))
    }

    override fun close() {
        runCatching { socket.sendClose(WebSocket.NORMAL_CLOSURE, "").get(5, TimeUnit.SECONDS) }
        // Chromium's helper processes outlive it for a moment and write into the profile: end them all first.
        val processes = process.descendants().toList() + process.toHandle()
        processes.forEach { it.destroy() }
        processes.forEach { handle ->
            runCatching { handle.onExit().get(10, TimeUnit.SECONDS) }.onFailure { handle.destroyForcibly() }
        }
        profile.toFile().deleteRecursively()
    }

    companion object {
        /** Starts Chromium with a [width]×[height] window and connects to its first page. */
        fun start(width: Int = 1400, height: Int = 900): HeadlessChromium {
            assumeInstalled()
            val executable = Chromium.executable()!!
            val profile = Files.createTempDirectory("rtcoord-chromium")
            val process =
                ProcessBuilder(
                        listOf(executable.toString()) +
                            Chromium.headlessFlags(profile) +
                            listOf(
                                "--remote-debugging-address=127.0.0.1",
                                "--remote-debugging-port=0",
                                "--window-size=$width,$height",
                                "about:blank",
                            )
                    )
                    .redirectErrorStream(true)
                    .redirectOutput(profile.resolve("chromium.log").toFile())
                    .start()
            try {
                val active = profile.resolve("DevToolsActivePort")
                val port =
                    awaitValue("Chromium's DevTools port", 60.seconds) {
                        runCatching { Files.readAllLines(active).firstOrNull()?.toIntOrNull() }.getOrNull()
                    }
                val http = HttpClient.newHttpClient()
                val pageSocket =
                    awaitValue("Chromium's page", 60.seconds) {
                        val list =
                            runCatching {
                                http
                                    .send(
                                        HttpRequest.newBuilder(URI("http://127.0.0.1:$port/json/list")).build(),
                                        HttpResponse.BodyHandlers.ofString(),
                                    )
                                    .body()
                            }
                                .getOrNull() ?: return@awaitValue null
                        Json.parseToJsonElement(list)
                            .jsonArray
                            .map { it.jsonObject }
                            .firstOrNull { it["type"]?.jsonPrimitive?.content == "page" }
                            ?.get("webSocketDebuggerUrl")
                            ?.jsonPrimitive
                            ?.content
                    }
                val replies = Replies()
                val socket = http.newWebSocketBuilder().buildAsync(URI(pageSocket), replies).get(60, TimeUnit.SECONDS)
                return HeadlessChromium(process, profile, socket, replies).also { it.send("Page.enable") }
            } catch (e: Throwable) {
                process.destroyForcibly()
                val log = Files.readString(profile.resolve("chromium.log")).takeLast(2000)
                profile.toFile().deleteRecursively()
                throw AssertionError("Chromium did not start: $log", e)
            }
        }

        /** Skips the test when Chromium is not installed, outside CI; fails it in CI. */
        fun assumeInstalled() {
            if (Chromium.executable() == null)
                missing("chromium is not installed (apt-get install chromium; .ci/run does it)")
        }

        private fun missing(why: String): Nothing {
            if (System.getenv("CI") != null) fail<Unit>(why) else assumeTrue(false, why)
            throw IllegalStateException(why)
        }
    }
}
