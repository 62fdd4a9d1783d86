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
import java.security.MessageDigest
import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.flow.onSubscription
import org.rtcoord.ComponentNode
import org.rtcoord.RtcException
import org.rtcoord.RtcTree
import org.rtcoord.cli.ComponentReport
import org.rtcoord.cli.json.OneLineJson

/**
 * The HTTP server of the live view: the page and its scripts from the jar, and the API it uses: `GET /api/snapshot`
 * (JSON), `GET /api/events` (server-sent events: a `snapshot`, then [LiveView]'s updates), `GET /api/component?path=`
 * (a component's details, read now) and, when [LiveView.operable], `POST /api/operate?path=&action=` with the
 * parameters the [PageOperation] needs. With a [token], every API request must carry it (`?token=` or `Authorization:
 * Bearer`). [log] receives one line per operation. A [Served.Replayed] recording is sent whole as one `replay` event;
 * its page cannot operate anything.
 */
internal class LiveServer(
    private val served: Served,
    private val token: String?,
    private val log: (String) -> Unit,
) : AutoCloseable {
    private var server: EmbeddedServer<*, *>? = null

    /** Starts listening on [address]:[port] (0: any free port) and returns the port. */
    suspend fun start(address: String, port: Int): Int {
        val started =
            embeddedServer(CIO, host = address, port = port) {
                install(SSE)
                // Before routing, so that no API answer (an event stream least of all) starts without the token.
                intercept(ApplicationCallPipeline.Plugins) {
                    if (call.request.path().startsWith("/api/") && !allowed(call)) finish()
                }
                routing {
                    staticResources("/", "org/rtcoord/cli/serve", index = "index.html")
                    staticResources("/lib", "META-INF/resources/webjars")
                    get("/api/snapshot") {
                        val snapshot =
                            when (served) {
                                is Served.Live -> OneLineJson.encodeToString(served.view.snapshot())
                                is Served.Replayed -> served.recording.snapshot()
                            }
                        call.respondText(snapshot, ContentType.Application.Json)
                    }
                    sse("/api/events") {
                        // A page that loses the server (restarted, say) tries again after this long.
                        send(data = "{}", event = "hello", retry = RETRY_MILLIS)
                        when (served) {
                            is Served.Live ->
                                served.view.updates
                                    .onSubscription {
                                        send(
                                            data = OneLineJson.encodeToString(served.view.snapshot()),
                                            event = "snapshot",
                                        )
                                    }
                                    .collect { send(data = it.json, event = it.kind) }
                            // Held open, so that the page does not ask again; it has everything.
                            is Served.Replayed -> {
                                send(data = served.recording.toJson(), event = "replay")
                                awaitCancellation()
                            }
                        }
                    }
                    get("/api/component") {
                        val path = call.request.queryParameters["path"]
                        val live =
                            served as? Served.Live
                                ?: return@get call.respondText(
                                    "a replay has the recorded states only, not the components",
                                    status = HttpStatusCode.NotFound,
                                )
                        val tree = live.tree
                        val component = path?.let { component(tree, it) }
                        if (component == null) {
                            call.respondText(
                                "no component at ${path ?: "(no path given)"}",
                                status = HttpStatusCode.NotFound,
                            )
                        } else {
                            val report =
                                try {
                                    OneLineJson.encodeToString(
                                        ComponentReport.read(tree, component, withConfiguration = true).toJson()
                                    )
                                } catch (e: RtcException) {
                                    OneLineJson.encodeToString(ComponentErrorJson(path, e.message ?: e.reason))
                                }
                            call.respondText(report, ContentType.Application.Json)
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
        val live = served as? Served.Live
        if (live == null || !live.view.operable) {
            log(
                "refused: $who asked to ${operation?.word ?: "operate"} $path, but the page is read-only (start with --operate)"
            )
            return call.respondText("read-only: start the server with --operate", status = HttpStatusCode.Forbidden)
        }
        val view = live.view
        val component = path?.let { component(live.tree, it) }
        if (operation == null || component == null) {
            return call.respondText(
                "action must be one of ${PageOperation.words}, and path a component",
                status = HttpStatusCode.BadRequest,
            )
        }
        val given = operation.parameters.associateWith { call.request.queryParameters[it] }
        val missing = given.filterValues { it == null }.keys
        if (missing.isNotEmpty()) {
            return call.respondText(
                "${operation.word} needs ${missing.joinToString(" and ")}",
                status = HttpStatusCode.BadRequest,
            )
        }
        val details = given.entries.joinToString("") { (name, value) -> " $name=$value" }
        val line = "${operation.word} $path$details (from $who)"
        val failure =
            try {
                operation.perform(live.tree, component, given.mapValues { it.value!! })
                null
            } catch (e: RtcException) {
                HttpStatusCode.Conflict to (e.message ?: e.reason)
            } catch (e: IllegalArgumentException) {
                // A port path that does not parse, say.
                HttpStatusCode.BadRequest to (e.message ?: e.toString())
            }
        val outcome = failure?.let { "failed: ${it.second}" } ?: "done"
        log("$line: $outcome")
        view.log("page", "$line: $outcome")
        if (failure == null) call.respondText("done") else call.respondText(failure.second, status = failure.first)
    }

    private suspend fun component(tree: RtcTree, path: String): ComponentNode? =
        try {
            tree.node(path) as? ComponentNode
        } catch (e: RtcException) {
            null
        } catch (e: IllegalArgumentException) {
            null
        }

    /** Whether [call] carries the token when one is required; answers 401 when it does not. */
    private suspend fun allowed(call: ApplicationCall): Boolean {
        val expected = token ?: return true
        val given =
            call.request.queryParameters["token"] ?: call.request.headers["Authorization"]?.removePrefix("Bearer ")
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
