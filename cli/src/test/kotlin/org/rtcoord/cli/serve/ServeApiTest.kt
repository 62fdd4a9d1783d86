package org.rtcoord.cli.serve

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.core.parse
import com.github.ajalt.clikt.parameters.groups.provideDelegate
import java.net.URI
import java.net.URLEncoder
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import kotlin.time.Duration.Companion.seconds
import kotlinx.coroutines.runBlocking
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.junit.jupiter.api.AfterEach
import org.junit.jupiter.api.Assertions.assertEquals
import org.junit.jupiter.api.Assertions.assertNull
import org.junit.jupiter.api.Assertions.assertTrue
import org.junit.jupiter.api.Test
import org.rtcoord.EventOptions
import org.rtcoord.LifeCycle
import org.rtcoord.RtcTree
import org.rtcoord.TreeConfig
import org.rtcoord.cli.Localisation
import org.rtcoord.fixtures.await

/** The live view's API, straight over HTTP: the snapshot, the event stream, details, operating and the token. */
class ServeApiTest {
    private val localisation = Localisation()
    private val tree = RtcTree(TreeConfig(listOf(localisation.naming.address), 3.seconds))
    private val http = HttpClient.newHttpClient()
    private val services = mutableListOf<LiveService>()

    @AfterEach
    fun stop() {
        services.forEach(LiveService::close)
        tree.close()
        localisation.close()
    }

    private fun serve(vararg options: String): String = runBlocking {
        val parsed = ServeOptionsCommand().apply { parse(listOf("--port", "0", *options)) }.serving.settings()
        val top = tree.node("/${localisation.naming.address}")
        LiveService.start(tree, top, null, EventOptions(), parsed) {}.also { services += it }.url.substringBefore('?')
    }

    private fun get(url: String, authorization: String? = null): HttpResponse<String> =
        http.send(
            HttpRequest.newBuilder(URI(url)).apply { authorization?.let { header("Authorization", it) } }.build(),
            HttpResponse.BodyHandlers.ofString(),
        )

    private fun post(url: String): HttpResponse<String> =
        http.send(
            HttpRequest.newBuilder(URI(url)).POST(HttpRequest.BodyPublishers.noBody()).build(),
            HttpResponse.BodyHandlers.ofString(),
        )

    private fun json(text: String): JsonObject = Json.parseToJsonElement(text).jsonObject

    private fun encoded(path: String) = URLEncoder.encode(path, Charsets.UTF_8)

    @Test
    fun `the snapshot holds the network, its managers and connections`() {
        val base = serve()
        val response = get("${base}api/snapshot")
        assertEquals(200, response.statusCode())
        val network = json(response.body())["network"]!!.jsonObject
        val states =
            network["components"]!!.jsonArray.associate {
                it.jsonObject["name"]!!.jsonPrimitive.content to it.jsonObject["state"]!!.jsonPrimitive.content
            }
        assertEquals(
            mapOf("laser0" to "ACTIVE", "gyro0" to "ACTIVE", "odometry0" to "ACTIVE", "laser_localise0" to "ACTIVE"),
            states,
        )
        val connections =
            network["connections"]!!
                .jsonArray
                .map { it.jsonObject }
                .map {
                    "${it["source"]!!.jsonPrimitive.content.substringAfterLast('/')}:${it["sourcePort"]!!.jsonPrimitive.content} -> " +
                        "${it["target"]!!.jsonPrimitive.content.substringAfterLast('/')}:${it["targetPort"]!!.jsonPrimitive.content} ${it["kind"]!!.jsonPrimitive.content}"
                }
        assertEquals(
            setOf(
                "laser0.rtc:laser -> laser_localise0.rtc:laser data",
                "odometry0.rtc:odo -> laser_localise0.rtc:odo data",
            ),
            connections.toSet(),
        )
        val hosted =
            network["managers"]!!.jsonArray.flatMap { manager ->
                manager.jsonObject["hosts"]!!.jsonArray.map { it.jsonPrimitive.content.substringAfterLast('/') }
            }
        assertEquals(
            setOf("laser0.rtc", "gyro0.rtc", "odometry0.rtc", "laser_localise0.rtc", "manager_slave"),
            hosted.toSet(),
        )
        assertTrue(
            network["contexts"]!!.jsonArray.any { it.jsonObject["id"]!!.jsonPrimitive.content == localisation.host }
        )
    }

    @Test
    fun `the event stream starts with a snapshot and carries each state change`() {
        val base = serve()
        val lines = LinkedBlockingQueue<String>()
        val stream =
            http
                .sendAsync(
                    HttpRequest.newBuilder(URI("${base}api/events")).build(),
                    HttpResponse.BodyHandlers.ofLines(),
                )
                .thenAccept { response -> response.body().forEach(lines::put) }
        try {
            val events = SseReader(lines)
            events.next("the snapshot") { it.first == "snapshot" }
            localisation.system.component("laser0").fail()
            val error =
                events.next("laser0 entering ERROR") { (kind, data) ->
                    kind == "event" && "laser0.rtc" in data && "\"new\":\"ERROR\"" in data
                }
            assertEquals("state", json(error.second)["kind"]!!.jsonPrimitive.content)
        } finally {
            stream.cancel(true)
        }
    }

    @Test
    fun `a component's details are read on request`() {
        val base = serve()
        val details = json(get("${base}api/component?path=${encoded(localisation.path("laser0.rtc"))}").body())
        assertEquals("laser0", details["instanceName"]!!.jsonPrimitive.content)
        assertEquals(
            listOf("laser"),
            details["ports"]!!.jsonArray.map { it.jsonObject["name"]!!.jsonPrimitive.content },
        )
        assertTrue(details["configuration"]!!.jsonObject["sets"]!!.jsonObject.isNotEmpty())
        assertEquals(404, get("${base}api/component?path=${encoded(localisation.path("nothing.rtc"))}").statusCode())
    }

    @Test
    fun `the page operates components only with --operate`() {
        val gyro = localisation.path("gyro0.rtc")
        val readOnly = serve()
        assertEquals(403, post("${readOnly}api/operate?path=${encoded(gyro)}&action=deactivate").statusCode())
        assertEquals(LifeCycle.ACTIVE, runBlocking { tree.component(gyro).state() })
        val operable = serve("--operate")
        assertEquals(200, post("${operable}api/operate?path=${encoded(gyro)}&action=deactivate").statusCode())
        await("gyro0 to be INACTIVE", 30.seconds) { runBlocking { tree.component(gyro).state() } == LifeCycle.INACTIVE }
        assertTrue(
            json(get("${operable}api/snapshot").body())["events"]!!.jsonArray.any {
                "deactivate $gyro" in it.jsonObject["text"].toString()
            }
        )
        assertEquals(400, post("${operable}api/operate?path=${encoded(gyro)}&action=explode").statusCode())
    }

    @Test
    fun `every operation is refused when read-only, and done with --operate`() {
        val laser = localisation.path("laser0.rtc")
        val readOnly = serve()
        for (operation in PageOperation.entries) {
            assertEquals(
                403,
                post("${readOnly}api/operate?path=${encoded(laser)}&action=${operation.word}").statusCode(),
                operation.word,
            )
        }
        val operable = serve("--operate")
        fun details() = json(get("${operable}api/component?path=${encoded(laser)}").body())
        fun operate(query: String) = post("${operable}api/operate?path=${encoded(laser)}&$query")
        assertEquals("connect needs port and to", operate("action=connect").body())

        val sets = details()["configuration"]!!.jsonObject["sets"]!!.jsonObject
        val (set, parameters) = sets.entries.first()
        val parameter = parameters.jsonObject.keys.first()
        assertEquals(200, operate("action=set&set=${encoded(set)}&name=${encoded(parameter)}&value=7").statusCode())
        assertEquals(
            "7",
            details()["configuration"]!!
                .jsonObject["sets"]!!
                .jsonObject[set]!!
                .jsonObject[parameter]!!
                .jsonPrimitive
                .content,
        )
        assertEquals(200, operate("action=activate-set&set=${encoded(set)}").statusCode())
        assertEquals(set, details()["configuration"]!!.jsonObject["active"]!!.jsonPrimitive.content)

        val connector =
            details()["ports"]!!
                .jsonArray
                .single()
                .jsonObject["connections"]!!
                .jsonArray
                .single()
                .jsonObject["id"]!!
                .jsonPrimitive
                .content
        assertEquals(200, operate("action=disconnect&port=laser&connector=${encoded(connector)}").statusCode())
        assertTrue(
            details()["ports"]!!.jsonArray.single().jsonObject["connections"]!!.jsonArray.isEmpty(),
            "laser0:laser disconnected",
        )
        assertEquals(
            200,
            operate("action=connect&port=laser&to=${encoded(localisation.path("laser_localise0.rtc:laser"))}")
                .statusCode(),
        )
        assertEquals(
            1,
            details()["ports"]!!.jsonArray.single().jsonObject["connections"]!!.jsonArray.size,
            "laser0:laser connected again",
        )
        val logged =
            json(get("${operable}api/snapshot").body())["events"]!!.jsonArray.map {
                it.jsonObject["text"]!!.jsonPrimitive.content
            }
        assertTrue(
            logged.any { it.startsWith("disconnect $laser port=laser connector=$connector") && it.endsWith(": done") },
            logged.joinToString("\n"),
        )
    }

    @Test
    fun `with a token every API request must carry it`() {
        val base = serve("--token", "s3cret")
        assertEquals(401, get("${base}api/snapshot").statusCode())
        assertEquals(401, get("${base}api/snapshot?token=wrong").statusCode())
        assertEquals(200, get("${base}api/snapshot?token=s3cret").statusCode())
        assertEquals(200, get("${base}api/snapshot", authorization = "Bearer s3cret").statusCode())
        assertEquals(401, get("${base}api/events").statusCode())
        // The page itself loads, and asks with the token it was opened with.
        assertEquals(200, get(base).statusCode())
    }

    @Test
    fun `the page and its libraries are served from the jar`() {
        val base = serve()
        val page = get(base)
        assertEquals(200, page.statusCode())
        Regex("""src="([^"]+)"""")
            .findAll(page.body())
            .map { it.groupValues[1] }
            .toList()
            .also { assertEquals(4, it.size) }
            .forEach { script -> assertEquals(200, get(base + script).statusCode(), script) }
    }

    @Test
    fun `another address than loopback without a token is warned about`() {
        fun exposure(vararg options: String) =
            ServeOptionsCommand().apply { parse(options.toList()) }.serving.settings().exposure()
        assertNull(exposure())
        assertNull(exposure("--listen", "0.0.0.0", "--token", "t"))
        val warning = exposure("--listen", "0.0.0.0", "--operate")
        assertEquals(
            "the page on 0.0.0.0 has no authentication: anyone who reaches it sees the system and can operate it; add a token to require one",
            warning,
        )
    }

    /** A command holding nothing but the options, to parse them as `serve` does. */
    private class ServeOptionsCommand : CliktCommand() {
        val serving by ServeOptions()

        override fun run() = Unit
    }
}

/** Server-sent events from a stream's lines: (event name, data). */
class SseReader(private val lines: LinkedBlockingQueue<String>) {
    /** The next event that [matches], waiting up to 60 s; fails naming [what]. */
    fun next(what: String, matches: (Pair<String, String>) -> Boolean = { true }): Pair<String, String> {
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60)
        var kind = "message"
        val data = StringBuilder()
        while (true) {
            val line =
                lines.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS)
                    ?: throw AssertionError("timed out waiting for $what")
            when {
                line.isEmpty() -> {
                    val event = kind to data.toString()
                    kind = "message"
                    data.setLength(0)
                    if (event.second.isNotEmpty() && matches(event)) return event
                }
                line.startsWith("event:") -> kind = line.removePrefix("event:").trim()
                line.startsWith("data:") -> data.append(line.removePrefix("data:").removePrefix(" "))
            }
        }
    }
}
