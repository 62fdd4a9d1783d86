package org.rtcoord.cli.serve

import org.rtcoord.EventOptions
import org.rtcoord.Node
import org.rtcoord.RtcTree
import org.rtcoord.dsl.Coordinator

/**
 * A page served by a [LiveServer], as `serve` and `run --serve` start it: of a [LiveView] of [Node]s below a top node
 * (recorded too, when the settings say so), or of a [Recording] replayed; [url] is where the page is.
 */
internal class LiveService
private constructor(
    private val view: LiveView?,
    private val recorder: LiveRecorder?,
    private val server: LiveServer,
    val url: String,
) : AutoCloseable {
    /** Adds a line of [source] (the coordinator, say) to the page's timeline. */
    fun log(source: String, line: String) {
        view?.log(source, line)
    }

    /** Stops serving, recording and following the system. */
    override fun close() {
        server.close()
        recorder?.close()
        view?.close()
    }

    companion object {
        /**
         * Reads the system below [top], starts following it (and [coordinator], if any) with [events], and serves the
         * page as [options] say. [log] receives each operation done from the page.
         */
        suspend fun start(
            tree: RtcTree,
            top: Node,
            coordinator: Coordinator?,
            events: EventOptions,
            options: ServeSettings,
            log: (String) -> Unit,
        ): LiveService {
            val view = LiveView(tree, top, coordinator, events, options.operate)
            view.start()
            var recorder: LiveRecorder? = null
            try {
                recorder = options.record?.let { LiveRecorder.start(view, it) }
                val server = LiveServer(Served.Live(tree, view), options.token, log)
                return LiveService(view, recorder, server, listen(server, options))
            } catch (e: Exception) {
                recorder?.close()
                view.close()
                throw e
            }
        }

        /** Serves [recording] to be replayed in the page, as [options] say. */
        suspend fun replay(recording: Recording, options: ServeSettings): LiveService {
            val server = LiveServer(Served.Replayed(recording), options.token) {}
            return LiveService(null, null, server, listen(server, options))
        }

        /** Starts [server] where [options] say; returns the page's address. */
        private suspend fun listen(server: LiveServer, options: ServeSettings): String {
            val port =
                try {
                    server.start(options.address, options.port)
                } catch (e: Exception) {
                    throw IllegalArgumentException(
                        "cannot serve on ${options.address}:${options.port}: ${e.message ?: e}",
                        e,
                    )
                }
            val host = if (':' in options.address) "[${options.address}]" else options.address
            return "http://$host:$port/" + (options.token?.let { "?token=$it" } ?: "")
        }
    }
}
