package org.rtcoord.cli.serve

import io.ktor.http.ContentType
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.ApplicationCall
import io.ktor.server.application.ApplicationCallPipeline
import io.ktor.server.application.call
import io.ktor.server.application.install
import io.ktor.server.cio.CIO
import io.ktor.server.engine.EmbeddedServer
import io.ktor.server.engine.embeddedServer
import io.ktor.server.http.content.staticResources
import io.ktor.server.plugins.origin
import io.ktor.server.request.path
import io.ktor.server.response.header
import io.ktor.server.response.respondText
import io.ktor.server.routing.get
import io.ktor.server.routing.post
import io.ktor.server.routing.routing
import io.ktor.server.sse.SSE
import io.ktor.server.sse.sse
import kotlinx.coroutines.flow.onSubscription
import org.rtcoord.ComponentNode
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.cli.ComponentReport
import org.rtcoord.cli.toJson
import java.security.MessageDigest

/**
 * The HTTP server of the live view: the page and its scripts from the jar, and the API it uses:
 * `GET /api/snapshot` (JSON), `GET /api/events` (server-sent events: a `snapshot`, then [LiveView]'s
 * updates), `GET /api/component?path=` (a component's details, read now) and, when [LiveView.operable],
 * `POST /api/operate?path=&action=`. With a [token], every API request must carry it (`?token=` or
 * `Authorization: Bearer`). [log] receives one line per operation.
 */
internal class LiveServer(
    private val tree: RtcTree,
    private val view: LiveView,
    private val token: String?,
    private val log: (String) -> Unit,
) : AutoCloseable {
    private var server: EmbeddedServer<*, *>? = null

    /** Starts listening on [address]:[port] (0: any free port) and returns the port. */
    suspend fun start(address: String, port: Int): Int {
        val started = embeddedServer(CIO, host = address, port = port) {
            install(SSE)
            // Before routing, so that no API answer (an event stream least of all) starts without the token.
            intercept(ApplicationCallPipeline.Plugins) {
                if (call.request.path().startsWith("/api/") && !allowed(call)) finish()
            }
            routing {
                staticResources("/", "org/rtcoord/cli/serve", index = "index.html")
                staticResources("/lib", "META-INF/resources/webjars")
                get("/api/snapshot") {
                    call.respondText(toJson(view.snapshot(), pretty = false), ContentType.Application.Json)
                }
                sse("/api/events") {
                    // A page that loses the server (restarted, say) tries again after this long.
                    send(data = "{}", event = "hello", retry = RETRY_MILLIS)
                    view.updates.onSubscription { send(data = toJson(view.snapshot(), pretty = false), event = "snapshot") }
                        .collect { send(data = it.json, event = it.kind) }
                }
                get("/api/component") {
                    val path = call.request.queryParameters["path"]
                    val component = path?.let { component(it) }
                    if (component == null) {
                        call.respondText("no component at ${path ?: "(no path given)"}", status = HttpStatusCode.NotFound)
                    } else {
                        val report = try {
                            ComponentReport.read(tree, component, withConfiguration = true).toJson()
                        } catch (e: RtcException) {
                            mapOf("path" to path, "error" to (e.message ?: e.reason))
                        }
                        call.respondText(toJson(report, pretty = false), ContentType.Application.Json)
                    }
                }
                post("/api/operate") {
                    operate(call)
                }
            }
        }
        started.startSuspend(wait = false)
        server = started
        return started.engine.resolvedConnectors().first().port
    }

    private suspend fun operate(call: ApplicationCall) {
        val path = call.request.queryParameters["path"]
        val operation = PageOperation.named(call.request.queryParameters["action"])
        val who = call.request.origin.remoteAddress
        if (!view.operable) {
            log("refused: $who asked to ${operation?.word ?: "operate"} $path, but the page is read-only (start with --operate)")
            return call.respondText("read-only: start the server with --operate", status = HttpStatusCode.Forbidden)
        }
        val component = path?.let { component(it) }
        if (operation == null || component == null) {
            return call.respondText("action must be activate, deactivate or reset, and path a component", status = HttpStatusCode.BadRequest)
        }
        val line = "${operation.word} $path (from $who)"
        try {
            operation.perform(component)
            log("$line: done")
            view.log("page", "$line: done")
            call.respondText("done")
        } catch (e: RtcException) {
            log("$line: failed: ${e.message ?: e.reason}")
            view.log("page", "$line: failed: ${e.message ?: e.reason}")
            call.respondText(e.message ?: e.reason, status = HttpStatusCode.Conflict)
        }
    }

    private suspend fun component(path: String): ComponentNode? = try {
        tree.node(path) as? ComponentNode
    } catch (e: RtcException) {
        null
    } catch (e: IllegalArgumentException) {
        null
    }

    /** Whether [call] carries the token when one is required; answers 401 when it does not. */
    private suspend fun allowed(call: ApplicationCall): Boolean {
        val expected = token ?: return true
        val given = call.request.queryParameters["token"] ?: call.request.headers["Authorization"]?.removePrefix("Bearer ")
        if (given != null && MessageDigest.isEqual(given.toByteArray(), expected.toByteArray())) return true
        call.response.header("Cache-Control", "no-store")
        call.respondText("a token is required: open the page as /?token=TOKEN", status = HttpStatusCode.Unauthorized)
        return false
    }

    /** Stops serving; open event streams end. */
    override fun close() {
        server?.stop(STOP_GRACE_MILLIS, STOP_TIMEOUT_MILLIS)
        server = null
    }

    private companion object {
        const val RETRY_MILLIS = 1000L
        const val STOP_GRACE_MILLIS = 100L
        const val STOP_TIMEOUT_MILLIS = 2000L
    }
}
