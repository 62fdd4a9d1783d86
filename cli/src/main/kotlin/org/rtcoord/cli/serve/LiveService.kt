package org.rtcoord.cli.serve

import org.rtcoord.EventOptions
import org.rtcoord.Node
import org.rtcoord.RtcTree
import org.rtcoord.dsl.Coordinator

/**
 * A [LiveView] of [Node]s below a top node served by a [LiveServer], as `serve` and `run --serve` start
 * it; [url] is where the page is.
 */
internal class LiveService private constructor(private val view: LiveView, private val server: LiveServer, val url: String) : AutoCloseable {
    /** Adds a line of [source] (the coordinator, say) to the page's timeline. */
    fun log(source: String, line: String) = view.log(source, line)

    /** Stops serving and following the system. */
    override fun close() {
        server.close()
        view.close()
    }

    companion object {
        /**
         * Reads the system below [top], starts following it (and [coordinator], if any) with [events],
         * and serves the page as [options] say. [log] receives each operation done from the page.
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
            val server = LiveServer(tree, view, options.token, log)
            val port = try {
                server.start(options.address, options.port)
            } catch (e: Exception) {
                view.close()
                throw IllegalArgumentException("cannot serve on ${options.address}:${options.port}: ${e.message ?: e}", e)
            }
            val host = if (':' in options.address) "[${options.address}]" else options.address
            val url = "http://$host:$port/" + (options.token?.let { "?token=$it" } ?: "")
            return LiveService(view, server, url)
        }
    }
}
