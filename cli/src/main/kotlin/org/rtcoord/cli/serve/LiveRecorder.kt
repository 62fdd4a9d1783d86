package org.rtcoord.cli.serve

import java.io.BufferedWriter
import java.io.IOException
import java.nio.file.Files
import java.nio.file.Path
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineName
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.flow.onSubscription
import kotlinx.coroutines.launch
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.encodeToJsonElement
import org.rtcoord.cli.json.OneLineJson

/**
 * Writes what [view] shows to [file] as JSON lines, as a page would receive it: the snapshot first, then every update,
 * each line `{"kind":…,"at":EPOCH_MILLIS,"data":…}` (see [Recording]). Each line is flushed as it is written, so that a
 * run that is killed leaves a recording up to its end.
 */
internal class LiveRecorder private constructor(private val writer: BufferedWriter) : AutoCloseable {
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.IO + CoroutineName("live-record"))
    private var closed = false

    private fun write(kind: String, data: JsonElement) {
        synchronized(this) {
            if (closed) return
            writer.write(Recording.line(kind, System.currentTimeMillis(), data))
            writer.newLine()
            writer.flush()
        }
    }

    /** Stops recording; the file holds every line written so far. */
    override fun close() {
        scope.cancel()
        synchronized(this) {
            closed = true
            writer.close()
        }
    }

    companion object {
        /** Starts recording [view] to [file] (replacing it); returns once the snapshot is written. */
        suspend fun start(view: LiveView, file: Path): LiveRecorder {
            val writer =
                try {
                    Files.newBufferedWriter(file)
                } catch (e: IOException) {
                    throw IllegalArgumentException("cannot record to $file: ${e.message ?: e}", e)
                }
            val recorder = LiveRecorder(writer)
            val started = CompletableDeferred<Unit>()
            recorder.scope.launch {
                view.updates
                    .onSubscription {
                        recorder.write("snapshot", OneLineJson.encodeToJsonElement(view.snapshot()))
                        started.complete(Unit)
                    }
                    .collect { recorder.write(it.kind, it.data) }
            }
            started.await()
            return recorder
        }
    }
}
