package org.rtcoord.cli

import java.util.concurrent.CopyOnWriteArraySet
import kotlin.time.Duration
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.selects.select
import sun.misc.Signal
import sun.misc.SignalHandler

/**
 * SIGINT and SIGTERM as a request to stop, for commands that run until stopped: the command then ends as it does when
 * its time is up (observers detached, a last line printed) and the process exits 0, as a service manager expects of a
 * service it stopped. Without this the JVM would end through its shutdown hooks while the command still runs, with
 * status 130 or 143, and a command racing those hooks fails (`removeShutdownHook` throws "Shutdown in progress"). A
 * second signal ends the process the JVM's way.
 */
internal class StopSignals : AutoCloseable {
    private val requested = CompletableDeferred<String>()
    private val previous = HashMap<String, SignalHandler>()

    init {
        waiting += this
        for (name in listOf("INT", "TERM")) {
            try {
                previous[name] =
                    Signal.handle(Signal(name)) { signal ->
                        requested.complete("SIG${signal.name}")
                        close()
                    }
            } catch (e: IllegalArgumentException) {
                // The JVM keeps the signal for itself (-Xrs, or a platform without it): it ends the process as before.
            }
        }
    }

    /** Stops the command as a signal would, for [reason] (what [await] returns). */
    fun stop(reason: String) {
        requested.complete(reason)
    }

    /**
     * Waits for a signal or [stop], at most [limit] (forever when null); returns the signal's name or the reason, or
     * null when the time was up.
     *
     * The limit is a `delay` raced against the request, not `withTimeoutOrNull`: under `runBlocking` a delay is kept by
     * the command's own event loop, while a timeout starts kotlinx's shared timer thread, which then lives as long as
     * the command (one thread more in every `watch --for` and `run --for`).
     */
    suspend fun await(limit: Duration?): String? =
        if (limit == null) requested.await()
        else
            coroutineScope {
                val time = launch { delay(limit) }
                select {
                    requested.onAwait { it }
                    time.onJoin { null }
                }
                    .also { time.cancel() }
            }

    /** Gives the signals back to the JVM. */
    @Synchronized
    override fun close() {
        waiting -= this
        previous.forEach { (name, handler) -> Signal.handle(Signal(name), handler) }
        previous.clear()
    }

    internal companion object {
        private val waiting = CopyOnWriteArraySet<StopSignals>()

        /**
         * Stops every command of this JVM that is running until stopped, as a SIGINT to its process would; false when
         * none is. For callers that run commands inside their own JVM (the tests), where a real signal would end the
         * caller too.
         */
        fun interrupt(): Boolean = waiting.onEach { it.stop("SIGINT") }.isNotEmpty()

        /**
         * Stops every command of this JVM that is running until stopped, its standard output having no reader any more:
         * it ends as after SIGTERM, with status 0.
         */
        fun outputClosed() {
            waiting.forEach { it.stop(OUTPUT_CLOSED) }
        }

        /** What a command stopped by [outputClosed] was stopped by. */
        private const val OUTPUT_CLOSED = "its output's reader leaving"
    }
}
